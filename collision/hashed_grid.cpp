// Non-template parts of the hashed grid (thesis 3.4): cell arithmetic and the default hash.
#include "collision/hashed_grid.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collision {

namespace {
// splitmix64's finaliser: every input bit affects every output bit.
std::uint64_t mix(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return x;
}

bool to_cell(double coordinate, double cell_size, int& out) {
    const double c = std::floor(coordinate / cell_size);
    if (!(c >= double(INT_MIN) && c <= double(INT_MAX))) return false;  // also NaN
    out = int(c);
    return true;
}
}  // namespace

std::size_t CellHash::operator()(const glm::ivec3& c) const noexcept {
    const auto u = [](int v) { return std::uint64_t(std::uint32_t(v)); };
    return std::size_t(mix(u(c.x) ^ mix(u(c.y) ^ mix(u(c.z)))));
}

std::uint64_t CellRange::count() const {
    if (!valid) return 0;
    std::uint64_t n = 1;
    for (int i = 0; i < 3; ++i) n *= std::uint64_t(std::int64_t(hi[i]) - std::int64_t(lo[i]) + 1);
    return n;
}

namespace detail {

double checked_cell_size(float cell_size) {
    if (!(cell_size > 0.0f) || !std::isfinite(cell_size))
        throw std::invalid_argument("HashedGrid: cell size must be finite and > 0, got " + std::to_string(cell_size));
    return cell_size;
}

}  // namespace detail

glm::ivec3 cell_of(const glm::vec3& p, double cell_size) {
    glm::ivec3 c(0);
    for (int i = 0; i < 3; ++i) {
        const double v = std::floor(double(p[i]) / cell_size);
        // Outside int range (or NaN): clamped, so a far point maps to the grid's edge cell.
        c[i] = v >= double(INT_MAX) ? INT_MAX : (v <= double(INT_MIN) ? INT_MIN : (v == v ? int(v) : 0));
    }
    return c;
}

CellRange cell_range(const glm::vec3& lo, const glm::vec3& hi, double cell_size) {
    CellRange r;
    for (int i = 0; i < 3; ++i) {
        if (!(lo[i] <= hi[i])) return r;  // inverted or NaN
        if (!to_cell(lo[i], cell_size, r.lo[i]) || !to_cell(hi[i], cell_size, r.hi[i])) return r;
    }
    std::uint64_t n = 1;
    for (int i = 0; i < 3; ++i) {
        n *= std::uint64_t(std::int64_t(r.hi[i]) - std::int64_t(r.lo[i]) + 1);
        if (n > HashedGridLimits::max_cells_per_object) return r;
    }
    r.valid = true;
    return r;
}

namespace detail {

void sort_unique(std::vector<std::uint32_t>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace detail

}  // namespace collision

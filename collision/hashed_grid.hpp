#pragma once
// The thesis's space partitioning (3.4): a uniform grid of cubic cells of side S, stored sparsely
// in a hash table keyed by the integer cell coordinates. An object is inserted by its bounding
// box into every cell the box touches; a query by box returns the ids of every object sharing a
// cell with it, each once.
//
// The thesis's defect (3.5.3): two different cells whose hashes collide returned each other's
// objects, because the key was not compared in full. Here the table is a std::unordered_map on
// the full key (glm::ivec3, compared by ==), so a collision only costs time; the hash is a
// template parameter so tests can force every cell to collide and show that no foreign id
// comes back.
//
// Cells: cell (i, j, k) is [i S, (i+1) S) x [j S, (j+1) S) x [k S, (k+1) S); a point p is in
// cell floor(p / S) (computed in double, so the division rounds once and floor is exact). A box
// touching a cell's lower face only at its boundary coordinate belongs to both cells (boxes are
// closed): the range is floor(lo / S) .. floor(hi / S).
// Complexity: insert is O(cells touched); query O(cells touched + ids found). Degenerates as the
// thesis says: S too large puts everything in one cell (all pairs), S too small costs memory.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "collision/shapes.hpp"

namespace collision {

// A well-mixed default hash of a cell (the three coordinates through a 64-bit mixer).
struct CellHash {
    std::size_t operator()(const glm::ivec3& c) const noexcept;
};

// The inclusive cell range a box [lo, hi] touches. valid = false for a non-finite or inverted
// box, a cell coordinate outside int range, or more than HashedGridLimits::max_cells_per_object
// cells (the cell size is then wrong for that object).
struct CellRange {
    glm::ivec3 lo{0}, hi{-1};
    bool valid = false;
    std::uint64_t count() const;
};

struct HashedGridLimits {
    static constexpr std::uint64_t max_cells_per_object = std::uint64_t(1) << 24;
};

glm::ivec3 cell_of(const glm::vec3& p, double cell_size);
CellRange cell_range(const glm::vec3& lo, const glm::vec3& hi, double cell_size);

namespace detail {
// HashedGrid's own steps, out of line: throws std::invalid_argument when cell_size is not
// finite and > 0; sorts ids and drops repeats.
double checked_cell_size(float cell_size);
void sort_unique(std::vector<std::uint32_t>& ids);
}  // namespace detail

template <class Hash = CellHash>
class HashedGrid {
public:
    using Id = std::uint32_t;

    explicit HashedGrid(float cell_size, Hash hash = Hash{})
        : cell_size_(detail::checked_cell_size(cell_size)), cells_(16, std::move(hash)) {}

    float cell_size() const { return float(cell_size_); }

    // The cell holding point p (coordinates beyond int range clamp to the edge cell).
    glm::ivec3 cell_of(const glm::vec3& p) const { return collision::cell_of(p, cell_size_); }

    // Inserts `id` into every cell the closed box [lo, hi] touches. Returns false (and inserts
    // nothing) for a box cell_range() rejects. Inserting the same id twice stores it twice per
    // cell; queries still return it once.
    bool insert(Id id, const glm::vec3& lo, const glm::vec3& hi) {
        const CellRange r = cell_range(lo, hi, cell_size_);
        if (!r.valid) return false;
        for_each_cell(r, [&](const glm::ivec3& c) { cells_[c].push_back(id); });
        return true;
    }
    bool insert(Id id, const Aabb& box) { return insert(id, box.min(), box.max()); }

    // Ids of the objects in every cell the box touches: sorted, each once. An invalid box gives
    // an empty result.
    std::vector<Id> query(const glm::vec3& lo, const glm::vec3& hi) const {
        std::vector<Id> out;
        const CellRange r = cell_range(lo, hi, cell_size_);
        if (!r.valid) return out;
        for_each_cell(r, [&](const glm::ivec3& c) {
            const std::span<const Id> ids = cell(c);
            out.insert(out.end(), ids.begin(), ids.end());
        });
        detail::sort_unique(out);
        return out;
    }
    std::vector<Id> query(const Aabb& box) const { return query(box.min(), box.max()); }

    // The thesis's neighbourhood query: objects in p's cell and the 26 cells around it.
    std::vector<Id> query_around(const glm::vec3& p) const {
        const glm::ivec3 c = cell_of(p);
        std::vector<Id> out;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const std::span<const Id> ids = cell(c + glm::ivec3(dx, dy, dz));
                    out.insert(out.end(), ids.begin(), ids.end());
                }
        detail::sort_unique(out);
        return out;
    }

    // The ids stored in one cell, by integer coordinates (empty when the cell holds nothing):
    // the lookup a 3D-DDA ray traversal needs.
    std::span<const Id> cell(const glm::ivec3& c) const {
        const auto it = cells_.find(c);
        if (it == cells_.end()) return {};
        return it->second;
    }

    std::size_t occupied_cells() const { return cells_.size(); }
    void clear() { cells_.clear(); }

private:
    template <class F>
    static void for_each_cell(const CellRange& r, F&& f) {
        for (int z = r.lo.z; z <= r.hi.z; ++z) {
            for (int y = r.lo.y; y <= r.hi.y; ++y) {
                for (int x = r.lo.x; x <= r.hi.x; ++x) {
                    f(glm::ivec3(x, y, z));
                    if (x == r.hi.x) break;  // x + 1 would overflow at INT_MAX
                }
                if (y == r.hi.y) break;
            }
            if (z == r.hi.z) break;
        }
    }
    double cell_size_;
    std::unordered_map<glm::ivec3, std::vector<Id>, Hash> cells_;
};

}  // namespace collision

#include "raytracer/render/integrators/photon_grid.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "collision/hashed_grid.hpp"

namespace sweeptrace {

std::uint32_t PhotonGrid::slot_of(const glm::vec3& p) const {
    const glm::ivec3 c = collision::cell_of(p, cell_size_);
    return static_cast<std::uint32_t>(collision::CellHash{}(c) % (start_.size() - 1));
}

void PhotonGrid::build(const std::vector<std::span<const Photon>>& runs, float cell_size) {
    cell_size_ = double(cell_size);
    std::vector<std::size_t> offset(runs.size() + 1, 0);
    for (std::size_t r = 0; r < runs.size(); ++r) offset[r + 1] = offset[r] + runs[r].size();
    const std::size_t n = offset.back();
    start_.assign(n + 1, 0);
    slot_.resize(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, runs.size(), 16), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t run = r.begin(); run < r.end(); ++run)
            for (std::size_t i = 0; i < runs[run].size(); ++i) slot_[offset[run] + i] = slot_of(runs[run][i].point);
    });
    // Counting sort: counts, their running sum (start_[s] = where slot s ends, then begins), and
    // a stable scatter. Counting and scattering go in parallel by ranges of slots, each range's
    // task reading every photon's slot and taking its own: a slot's photons keep their given order
    // whatever the number of tasks, and no two tasks write the same place.
    const std::size_t parts = std::max<std::size_t>(1, static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()));
    const auto by_slot_range = [&](auto&& take) {
        tbb::parallel_for(std::size_t(0), parts, [&](std::size_t p) {
            const std::size_t lo = n * p / parts, hi = n * (p + 1) / parts;
            for (std::size_t run = 0, i = 0; run < runs.size(); ++run)
                for (std::size_t j = 0; j < runs[run].size(); ++j, ++i)
                    if (slot_[i] >= lo && slot_[i] < hi) take(slot_[i], runs[run][j]);
        });
    };
    by_slot_range([&](std::uint32_t slot, const Photon&) { ++start_[slot + 1]; });
    for (std::size_t s = 1; s <= n; ++s) start_[s] += start_[s - 1];
    photons_.resize(n);
    by_slot_range([&](std::uint32_t slot, const Photon& photon) { photons_[start_[slot]++] = &photon; });
    // start_[s] now holds where slot s ends: shift back to where it begins.
    for (std::size_t s = n; s > 0; --s) start_[s] = start_[s - 1];
    if (n > 0) start_[0] = 0;
}

int PhotonGrid::near_slots(const glm::vec3& p, float r, std::uint32_t* slots) const {
    const glm::vec3 d(r);
    const glm::ivec3 lo = collision::cell_of(p - d, cell_size_), hi = collision::cell_of(p + d, cell_size_);
    int n = 0;
    // Side >= 2 r: two cells per axis, three when p - r or p + r falls on a cell's face.
    for (int z = lo.z; z <= hi.z && z - lo.z < 3; ++z)
        for (int y = lo.y; y <= hi.y && y - lo.y < 3; ++y)
            for (int x = lo.x; x <= hi.x && x - lo.x < 3; ++x) {
                const auto s = static_cast<std::uint32_t>(collision::CellHash{}(glm::ivec3(x, y, z)) % (start_.size() - 1));
                if (std::find(slots, slots + n, s) == slots + n) slots[n++] = s;
            }
    return n;
}

}  // namespace sweeptrace

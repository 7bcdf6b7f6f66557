#pragma once
// The thesis's measurements (§4) redone for rays: brute force, the 8-octant subdivision, the
// hashed uniform grid with a 3D-DDA, the native BVH and Embree, on icospheres of 320 to
// 1.3 million triangles: build time, single-thread Mrays/s, and hit/miss agreement with the BVH.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace sweeptrace::accuracy {

struct StructureRow {
    std::string structure;
    std::size_t triangles = 0;
    double build_seconds = 0.0;
    std::size_t rays = 0;  // traced within the time budget
    double mrays_per_s = 0.0;
    std::size_t mismatches = 0;  // hit/miss or triangle differs from the BVH on the same rays
};

// Icosphere subdivision levels `min_level` .. `max_level` (level L: 20 * 4^L triangles); each
// structure traces up to `max_rays` rays, stopping after `budget_seconds`.
std::vector<StructureRow> measure_structures(int min_level, int max_level, std::size_t max_rays,
                                             double budget_seconds, std::uint64_t seed);

void write_structures_csv(std::ostream& out, const std::vector<StructureRow>& rows);
void write_structures_markdown(std::ostream& out, const std::vector<StructureRow>& rows);

}  // namespace sweeptrace::accuracy

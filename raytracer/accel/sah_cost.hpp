#pragma once
// The SAH cost of a built tree, one formula for every width so trees compare:
//   cost = sum over inner nodes of A(node) / A(root) * 1  +  sum over leaves of A(leaf) / A(root) * primitives
// with A the surface area of the node's box: the expected number of node visits plus
// primitive tests of a ray that meets the root box, rays distributed uniformly in direction
// and position (MacDonald & Booth 1990). A wide node's visit counts 1 (its children's boxes
// are tested at once), which is what the wide traversal pays.
#include "collision/bvh.hpp"

namespace sweeptrace {

// Surface area, without the factor 1/2 of Bounds3::half_area (ratios do not care).
inline double surface_area(const glm::vec3& lo, const glm::vec3& hi) {
    if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return 0.0;
    const double dx = double(hi.x) - lo.x, dy = double(hi.y) - lo.y, dz = double(hi.z) - lo.z;
    return 2.0 * (dx * dy + dy * dz + dz * dx);
}

double sah_cost(const collision::Bvh& bvh);

}  // namespace sweeptrace

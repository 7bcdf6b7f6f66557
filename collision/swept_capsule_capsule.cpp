// Capsule-capsule, swept (thesis 3.1.5): Minkowski reduction to one ray cast. A Y-aligned
// capsule is its vertical core segment grown by its radius; the Minkowski sum of two of them is
// (core1 + core2) grown by r1 + r2, and the sum of two vertical segments of lengths h1, h2 is a
// vertical segment of length h1 + h2. So the sum is again a Y-aligned capsule with summed
// radius and summed height, centred at the still capsule's centre: the moving centre's path is
// cast against it (intersect_capsule.cpp). The thesis instead ran its sphere and cylinder
// sweeps on the parts and kept the nearest hit. Already overlapping -> t = 0.
// Result: normal = the grown capsule's outward normal (still -> moving). Point: q = centre at
// contact - normal (r1 + r2) lies on the grown core; its height clamped to the still core and
// pushed out by the still radius along the normal is on both capsules.
// t error: intersect_capsule.cpp's bound. Degenerate: radius <= 0, height < 0, non-finite
// input -> no hit.
#include <algorithm>

#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "collision/detail/swept_common.hpp"

namespace collision {

TimeOfImpact sweep(const Capsule& moving, const glm::vec3& motion, const Capsule& still) {
    using namespace detail;
    if (!finite(motion)) return {};
    const double grown_radius = double(moving.radius) + double(still.radius);
    auto point_on_still = [&](const glm::vec3& p, const glm::vec3& n) {
        const dvec3 c = to_double(still.center), dn = to_double(n);
        const dvec3 q = to_double(p) - dn * grown_radius;  // on the grown core
        const double half = 0.5 * double(still.height);
        return glm::vec3(dvec3(c.x, std::clamp(q.y, c.y - half, c.y + half), c.z) + dn * double(still.radius));
    };
    const Contact now = overlap(moving, still);  // also rejects degenerate capsules
    if (now.hit) {
        const dvec3 fallback = to_double(moving.center) - to_double(still.center);
        TimeOfImpact r = overlapping_at_start(now, {}, fallback, motion);
        r.point = point_on_still(moving.center + now.displacement, r.normal);
        return r;
    }
    if (!valid_upright(moving.center, moving.radius, moving.height) || !valid_upright(still.center, still.radius, still.height))
        return {};
    return cast_against(moving.center, motion,
                        Capsule{still.center, moving.radius + still.radius, moving.height + still.height}, point_on_still);
}

}  // namespace collision

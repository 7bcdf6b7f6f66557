// Sphere-sphere, swept (thesis 3.1.2): the moving centre's path against the still sphere grown
// by the moving radius (Minkowski sum: a sphere of radius r1 + r2), cast with the robust ray-
// sphere test (intersect_sphere.cpp: stable quadratic with closest-approach refinement; the
// thesis's textbook quadratic is thesis::intersect). Already overlapping (discrete test,
// touching included) -> t = 0.
// Result: normal = outward normal of the grown sphere at the hit (still -> moving); point =
// still centre + r2 * normal, on both spheres at time t. t error: intersect_sphere.cpp's bound.
// Degenerate: radius <= 0 or non-finite input -> no hit; zero motion -> only the t = 0 answer.
#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "collision/detail/swept_common.hpp"

namespace collision {

TimeOfImpact sweep(const Sphere& moving, const glm::vec3& motion, const Sphere& still) {
    using namespace detail;
    if (!finite(motion)) return {};
    const Contact now = overlap(moving, still);  // also rejects degenerate spheres
    auto point_on_still = [&](const glm::vec3&, const glm::vec3& n) { return still.center + n * still.radius; };
    if (now.hit) {
        const dvec3 fallback = to_double(moving.center) - to_double(still.center);
        TimeOfImpact r = overlapping_at_start(now, {}, fallback, motion);
        r.point = point_on_still(moving.center, r.normal);
        return r;
    }
    if (!valid_radius(moving.radius) || !valid_radius(still.radius)) return {};
    return cast_against(moving.center, motion, Sphere{still.center, moving.radius + still.radius}, point_on_still);
}

}  // namespace collision

// Cylinder-cylinder, swept (thesis 3.1.4 "Válec a válec spojitě"): the moving centre's path
// against the still cylinder grown by the moving one -- exact, since the Minkowski sum of two
// Y-aligned cylinders is the Y-aligned cylinder of summed radius and summed height -- cast
// with the ray-cylinder test (intersect_cylinder.cpp; the thesis's caps + projected side is
// thesis::intersect). Already overlapping (discrete test, touching included) -> t = 0.
// Result: normal = the grown cylinder's normal at the hit (side: horizontal; caps: +-Y);
// point = the moving centre at time t with y clamped to the still cylinder's height and (x, z)
// pulled within its radius: in both cylinders (the offsets left are at most the moving
// cylinder's radius and half-height). t error: intersect_cylinder.cpp's bound.
// Degenerate: radius <= 0, height < 0, non-finite input -> no hit; two disks (both heights 0)
// can only be found overlapping at t = 0.
#include <algorithm>

#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "collision/detail/swept_common.hpp"

namespace collision {

TimeOfImpact sweep(const Cylinder& moving, const glm::vec3& motion, const Cylinder& still) {
    using namespace detail;
    if (!finite(motion)) return {};
    auto point_in_still = [&](const glm::vec3& p, const glm::vec3&) {
        const dvec3 c = to_double(still.center), q = to_double(p);
        const double half = 0.5 * double(still.height);
        dvec3 out(q.x, std::clamp(q.y, c.y - half, c.y + half), q.z);
        const dvec3 radial(q.x - c.x, 0.0, q.z - c.z);
        const double len = glm::length(radial);
        if (len > double(still.radius)) out = dvec3(c.x, out.y, c.z) + radial * (double(still.radius) / len);
        return glm::vec3(out);
    };
    const Contact now = overlap(moving, still);  // also rejects degenerate cylinders
    if (now.hit) return overlapping_at_start(now, point_in_still(moving.center, {}), {}, motion);
    if (!valid_upright(moving.center, moving.radius, moving.height) || !valid_upright(still.center, still.radius, still.height))
        return {};
    return cast_against(moving.center, motion,
                        Cylinder{still.center, moving.radius + still.radius, moving.height + still.height}, point_in_still);
}

}  // namespace collision

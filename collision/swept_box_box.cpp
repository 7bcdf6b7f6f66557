// Box-box, swept (thesis 3.1.4): the moving centre's path against the still box grown by the
// moving box's size (Minkowski sum of two axis-aligned boxes: a box of summed size), cast with
// the slab test (intersect_aabb.cpp; the thesis's six face planes are thesis::intersect).
// Already overlapping (discrete test, touching included) -> t = 0.
// Result: normal = the grown box's face normal at the hit (+-axis, still -> moving); point =
// the moving centre at time t clamped into the still box, which lies in both boxes (per axis
// the clamped distance is at most the moving half-size, since the centre is on the grown box).
// t error: intersect_aabb.cpp's bound for the grown box.
// Degenerate: negative or non-finite sizes, non-finite input -> no hit; two boxes flat on the
// same axis (summed size 0 there) can only be found overlapping at t = 0.
#include <glm/common.hpp>

#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "collision/detail/swept_common.hpp"

namespace collision {

TimeOfImpact sweep(const Aabb& moving, const glm::vec3& motion, const Aabb& still) {
    using namespace detail;
    if (!finite(motion)) return {};
    auto point_in_still = [&](const glm::vec3& p, const glm::vec3&) { return glm::clamp(p, still.min(), still.max()); };
    const Contact now = overlap(moving, still);  // also rejects degenerate boxes
    if (now.hit) return overlapping_at_start(now, point_in_still(moving.center, {}), {}, motion);
    if (!valid_box(moving.center, moving.size) || !valid_box(still.center, still.size)) return {};
    return cast_against(moving.center, motion, Aabb{still.center, moving.size + still.size}, point_in_still);
}

}  // namespace collision

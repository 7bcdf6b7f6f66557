#pragma once
// The box a moving box sweeps over one step (§2.2's continuous motion, bounded instead of
// tested): what a BVH over moving shapes needs, so that a ray at any time in the step meets the
// shape only inside its node's box.
//
// Translation: a box moving by `motion` covers its Minkowski sum with the segment [0, motion],
// the reduction every swept test here makes (swept.hpp); boxed, that is exactly the union of the
// start and end boxes (swept_bounds(box, motion)).
//
// Any smooth motion (rotation, changing scale): each point p(t), t in [0, 1], of a C^2 path
// lies within |p''|max / 8 of its chord p(0) + t (p(1) - p(0)) (the interpolation error of
// linear interpolation: |p(t) - chord(t)| <= t (1 - t) / 2 |p''|max <= |p''|max / 8), and the
// chord lies in the box of p(0) and p(1). So a shape whose every point is in `start` at t = 0,
// in `end` at t = 1, and accelerates by at most `max_acceleration` (in the step's units) stays
// within box(start U end) grown by max_acceleration / 8 on every side
// (swept_bounds(start, end, max_acceleration)). Exact for translation (acceleration 0). The
// grown sides are rounded outward by one float step, so the float box holds the exact one.
#include <glm/vec3.hpp>

#include "collision/bounds3.hpp"
#include "collision/float_error.hpp"

namespace collision {

inline Bounds3 swept_bounds(const Bounds3& start, const Bounds3& end, float max_acceleration) {
    if (start.empty() || end.empty()) return Bounds3{};
    Bounds3 out = start;
    out.extend(end);
    if (max_acceleration > 0.0f) {
        const float grow = next_float_up(max_acceleration * 0.125f);  // the product by 1/8 is exact; up for the caller's rounding
        for (int a = 0; a < 3; ++a) {
            out.lo[a] = next_float_down(out.lo[a] - grow);
            out.hi[a] = next_float_up(out.hi[a] + grow);
        }
    }
    return out;
}

inline Bounds3 swept_bounds(const Bounds3& box, const glm::vec3& motion) {
    if (box.empty()) return box;
    Bounds3 end;
    for (int a = 0; a < 3; ++a) {
        // box + motion rounds: outward by one step, so `end` holds the exact moved box.
        end.lo[a] = next_float_down(box.lo[a] + motion[a]);
        end.hi[a] = next_float_up(box.hi[a] + motion[a]);
    }
    return swept_bounds(box, end, 0.0f);
}

}  // namespace collision

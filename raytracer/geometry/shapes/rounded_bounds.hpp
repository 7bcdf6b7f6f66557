#pragma once
// Object-space boxes rounded outward, so that a box computed in float holds the exact shape.
#include <glm/vec3.hpp>

#include "collision/bounds3.hpp"
#include "collision/float_error.hpp"

namespace sweeptrace {

// center +- half, rounded outward: center - half is rounded to nearest, so one step down
// brings it to or below the exact value (and likewise up).
inline collision::Bounds3 centred_bounds(const glm::vec3& center, const glm::vec3& half) {
    collision::Bounds3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = collision::next_float_down(center[a] - half[a]);
        b.hi[a] = collision::next_float_up(center[a] + half[a]);
    }
    return b;
}

// Box of points each computed with at most two additions from values of magnitude <= m:
// padded by gamma(2) m per axis.
inline collision::Bounds3 padded_bounds(const collision::Bounds3& b, const glm::vec3& m) {
    return collision::Bounds3{b.lo - collision::gamma(2) * m, b.hi + collision::gamma(2) * m};
}

}  // namespace sweeptrace

#pragma once
// Finiteness of a value or of every coordinate of a vector (NaN and infinities fail): the input
// check of the routines, the BVH builder and the image diff, in one place.
#include <cmath>

#include <glm/vec3.hpp>

namespace collision {

inline bool finite(float x) { return std::isfinite(x); }

template <typename T, glm::qualifier Q>
inline bool finite(const glm::vec<3, T, Q>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace collision

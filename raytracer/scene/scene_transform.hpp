#pragma once
// The building blocks of an object's transform, in double so that a chain of steps loses no more
// than the final rounding to float (Transform stores float matrices).
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace {

// Rotation by `degrees` (right-handed, counter-clockwise looking down the axis) about `axis`
// (any non-zero length), built from the unit quaternion (cos θ/2, sin θ/2 · axis) as the thesis
// does (§2.6: no Euler angles, no gimbal lock). Entries are within a few double ulps of the exact
// rotation; after rounding to float they are within 0.5 float ulp + that.
glm::dmat4 rotation_matrix(const glm::dvec3& axis, double degrees);

glm::dmat4 translation_matrix(const glm::dvec3& offset);
glm::dmat4 scale_matrix(const glm::dvec3& factors);

}  // namespace sweeptrace

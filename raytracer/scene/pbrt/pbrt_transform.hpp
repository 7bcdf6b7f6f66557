#pragma once
// pbrt-v4's transform statements as matrices, and the split of an affine matrix into the steps
// our scene JSON takes (rotate, scale by positive factors, rotate, translate).
//
// pbrt composes every statement on the right of the current transformation matrix (CTM):
// `Translate` makes CTM = CTM * T, so the statement nearest a shape acts on it first. `Transform`
// and `ConcatTransform` take 16 numbers column by column (the translation is numbers 13-15).
// pbrt's `Rotate` is the usual right-handed rotation matrix about the axis; pbrt's camera space is
// left-handed (x right, y up, z forward), which the camera conversion handles, not these matrices.
#include <optional>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace::pbrt {

glm::dmat4 matrix_from_pbrt(const double* m);  // column by column, as the file has them
// pbrt's LookAt: the camera-from-world matrix. nullopt when `up` is parallel to the view direction
// or eye == look.
std::optional<glm::dmat4> look_at(const glm::dvec3& eye, const glm::dvec3& look, const glm::dvec3& up);

double det3(const glm::dmat4& m);

// M's linear part = rotation * diag(scale) * pre_rotation, each rotation proper and scale > 0 (an
// SVD by Jacobi's method on M^T M, to double rounding). nullopt when the linear part is singular
// (some scale below 1e-12 of the largest) or mirrors (det < 0): our scene transforms do not mirror.
struct AffineSteps {
    glm::dmat3 pre_rotation{1.0};
    glm::dvec3 scale{1.0};
    glm::dmat3 rotation{1.0};
    glm::dvec3 translation{0.0};
};
std::optional<AffineSteps> split_affine(const glm::dmat4& m);

// A proper rotation matrix as (unit axis, degrees), right-handed; degrees 0 for the identity.
void axis_angle(const glm::dmat3& r, glm::dvec3& axis, double& degrees);

}  // namespace sweeptrace::pbrt

#include "raytracer/geometry/transform.hpp"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace sweeptrace {

Transform Transform::from_matrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) throw std::invalid_argument("transform has a non-finite entry");
    // A singular (or numerically near-singular) matrix flattens the object: no meaningful inverse.
    // Judged scale-free, so tiny and huge objects stay valid: |det| against the product of the
    // column lengths (Hadamard: equal for orthogonal axes of any lengths, 0 when flattened).
    const glm::dmat3 linear = glm::dmat3(glm::dmat4(m));
    const double det = glm::determinant(linear);
    const double axes = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    if (!(axes > 0.0) || !(std::abs(det) > 1e-6 * axes))
        throw std::invalid_argument("transform is singular (a scale of 0, or axes nearly parallel)");
    Transform t;
    t.to_world = m;
    // Inverted in double and rounded once, so each entry of to_object is within machine_epsilon
    // (relative) of the exact inverse of the float to_world: the object-space ray's error bound
    // (geometry/object_space.cpp) relies on it.
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(m));
    t.to_object = glm::mat4(inverse);
    t.normal_to_world = glm::mat3(glm::transpose(glm::dmat3(inverse)));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(t.to_object[c][r])) throw std::invalid_argument("transform's inverse overflows float");
    t.identity = (m == glm::mat4(1.0f));
    return t;
}

}  // namespace sweeptrace

#include "raytracer/geometry/transform.hpp"

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>

namespace sweeptrace {

Transform Transform::from_matrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) throw std::invalid_argument("transform has a non-finite entry");
    const glm::mat3 linear(m);
    const float det = glm::determinant(linear);
    // A singular (or numerically near-singular) matrix flattens the object: no meaningful inverse.
    if (!std::isfinite(det) || std::abs(det) < 1e-12f) throw std::invalid_argument("transform is singular (a scale of 0?)");
    Transform t;
    t.to_world = m;
    t.to_object = glm::inverse(m);
    t.normal_to_world = glm::inverseTranspose(linear);
    t.identity = (m == glm::mat4(1.0f));
    return t;
}

}  // namespace sweeptrace

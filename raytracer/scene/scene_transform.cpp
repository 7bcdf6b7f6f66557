#include "raytracer/scene/scene_transform.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace sweeptrace {

glm::dmat4 rotation_matrix(const glm::dvec3& axis, double degrees) {
    const double half = 0.5 * degrees * std::numbers::pi / 180.0;
    const glm::dvec3 u = glm::normalize(axis);
    const double w = std::cos(half);
    const double s = std::sin(half);
    const double x = s * u.x, y = s * u.y, z = s * u.z;
    // glm is column-major: m[column][row].
    glm::dmat4 m(1.0);
    m[0][0] = 1.0 - 2.0 * (y * y + z * z);
    m[0][1] = 2.0 * (x * y + w * z);
    m[0][2] = 2.0 * (x * z - w * y);
    m[1][0] = 2.0 * (x * y - w * z);
    m[1][1] = 1.0 - 2.0 * (x * x + z * z);
    m[1][2] = 2.0 * (y * z + w * x);
    m[2][0] = 2.0 * (x * z + w * y);
    m[2][1] = 2.0 * (y * z - w * x);
    m[2][2] = 1.0 - 2.0 * (x * x + y * y);
    return m;
}

glm::dmat4 translation_matrix(const glm::dvec3& offset) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(offset, 1.0);
    return m;
}

glm::dmat4 scale_matrix(const glm::dvec3& factors) {
    glm::dmat4 m(1.0);
    m[0][0] = factors.x;
    m[1][1] = factors.y;
    m[2][2] = factors.z;
    return m;
}

}  // namespace sweeptrace

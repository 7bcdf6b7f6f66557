#include "raytracer/render/sampling/equal_area_octahedral.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

glm::vec3 equal_area_square_to_sphere(const glm::vec2& p) {
    const float u = 2.0f * p.x - 1.0f, v = 2.0f * p.y - 1.0f;
    const float a = std::abs(u), b = std::abs(v);
    const float signed_distance = 1.0f - (a + b);  // > 0 inside the diamond: the upper hemisphere
    const float r = 1.0f - std::abs(signed_distance);
    // At r = 0 (the centre, or a corner) the azimuth is undefined and sin(theta) = 0: any phi.
    const float phi = (r == 0.0f ? 1.0f : (b - a) / r + 1.0f) * (kPi / 4.0f);
    const float z = std::copysign(1.0f - r * r, signed_distance);
    const float sin_theta = r * std::sqrt(std::max(2.0f - r * r, 0.0f));
    // copysign, not a comparison, so a signed zero on a folded edge keeps its side.
    return {std::copysign(std::cos(phi), u) * sin_theta, std::copysign(std::sin(phi), v) * sin_theta, z};
}

glm::vec2 equal_area_sphere_to_square(const glm::vec3& d) {
    const float x = std::abs(d.x), y = std::abs(d.y), z = std::abs(d.z);
    const float len = glm::length(d);
    // 1 - |z| / len without its cancellation near the poles.
    const float r = std::sqrt((x * x + y * y) / (len * (len + z)));
    const float phi = std::atan2(y, x) * (2.0f / kPi);  // in [0, 1]
    float v = phi * r, u = r - v;
    if (d.z < 0.0f) {  // the lower hemisphere: the outer triangle, a + b = 2 - r
        const float swapped = u;
        u = 1.0f - v;
        v = 1.0f - swapped;
    }
    return {0.5f * (std::copysign(u, d.x) + 1.0f), 0.5f * (std::copysign(v, d.y) + 1.0f)};
}

}  // namespace sweeptrace

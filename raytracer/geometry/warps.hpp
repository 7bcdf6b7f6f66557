#pragma once
// Warps from the unit square to directions and points, each with the density it produces, and
// the orthonormal frame they are expressed in. Geometry-level: shapes sample their surfaces with
// them (geometry/shapes/), the renderer its directions (render/).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 1.0f / kPi;
// The largest float below 1: where a uniform or a map onto [0, 1) is clamped to stay inside.
inline constexpr float kBelowOne = 0x1.fffffep-1f;

// Orthonormal frame around a unit vector n (Duff et al. 2017, branchless, no singularity at the
// poles): local (x, y, z) with z along n.
struct Frame {
    glm::vec3 s, t, n;

    explicit Frame(const glm::vec3& normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        s = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        t = glm::vec3(b, sign + n.y * n.y * a, -n.y);
    }
    glm::vec3 to_local(const glm::vec3& v) const { return {glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)}; }
    glm::vec3 to_world(const glm::vec3& v) const { return v.x * s + v.y * t + v.z * n; }
};

// Shirley-Chiu concentric map: uniform on the unit disk, low distortion. Density 1/pi.
inline glm::vec2 concentric_disk(float u1, float u2) {
    const float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
    if (a == 0.0f && b == 0.0f) return glm::vec2(0.0f);
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (kPi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = (kPi / 2.0f) - (kPi / 4.0f) * (a / b);
    }
    return r * glm::vec2(std::cos(phi), std::sin(phi));
}

// Cosine-weighted hemisphere around +z (Malley's method). Density cos(theta) / pi.
inline glm::vec3 cosine_hemisphere(float u1, float u2) {
    const glm::vec2 d = concentric_disk(u1, u2);
    return {d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y))};
}

// Uniform on the unit sphere. Density 1 / (4 pi).
inline glm::vec3 uniform_sphere(float u1, float u2) {
    const float z = 1.0f - 2.0f * u1;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Uniform over the cone of directions around +z with 1 - cos(theta_max) = `one_minus_cos_max`
// (passed as such so narrow cones, e.g. a small far light, keep their precision).
// Density 1 / (2 pi one_minus_cos_max).
inline glm::vec3 uniform_cone(float u1, float u2, float one_minus_cos_max) {
    const float x = u1 * one_minus_cos_max;  // 1 - cos(theta)
    const float cos_theta = 1.0f - x;
    const float sin_theta = std::sqrt(std::max(0.0f, x * (2.0f - x)));
    const float phi = 2.0f * kPi * u2;
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

inline float uniform_cone_pdf(float one_minus_cos_max) { return 1.0f / (2.0f * kPi * one_minus_cos_max); }

// Uniform on a triangle, returned as barycentrics (b0, b1) of its first two vertices.
// Density 1 / area.
inline glm::vec2 uniform_triangle(float u1, float u2) {
    const float su = std::sqrt(u1);
    return {1.0f - su, u2 * su};
}

}  // namespace sweeptrace

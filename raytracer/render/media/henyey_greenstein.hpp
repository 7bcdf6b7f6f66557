#pragma once
// The Henyey-Greenstein phase function (1941), the one phase function of our media (pbrt-v4's
// and Tungsten's default). cos_theta is measured between the direction the light was travelling
// (the ray's) and the scattered one, so g > 0 scatters forward:
//   p(cos_theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos_theta)^(3/2)),   integral over the sphere 1.
// Sampling inverts its CDF in cos_theta; the density of a sample is p itself (the sample is exact).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

inline float hg_phase(float cos_theta, float g) {
    const float denom = 1.0f + g * g - 2.0f * g * cos_theta;
    return (1.0f - g * g) / (4.0f * kPi * denom * std::sqrt(denom));
}

// cos_theta of a sample from uniform u. The textbook inverse (1 + g^2 - s^2) / (2 g), with
// s = (1 - g^2) / (1 - g + 2 g u), cancels catastrophically as g -> 0 (and is 0/0 at g = 0, which
// is why renderers switch to the isotropic formula below some |g|, sampling a slightly different
// density than they evaluate). Multiplied out, the same expression has no division by g:
//   cos_theta = ((2u - 1)(1 + g^2) + 2g(u^2 - u + 1) + 2g^3(u^2 - u)) / (1 - g + 2 g u)^2,
// which is 2u - 1 at g = 0 and exact (to rounding) for every g in (-1, 1).
inline float hg_sample_cos(float g, float u) {
    const float a = 1.0f - g + 2.0f * g * u;
    const float uu = u * u - u;
    const float num = (2.0f * u - 1.0f) * (1.0f + g * g) + 2.0f * g * (uu + 1.0f) + 2.0f * g * g * g * uu;
    return std::clamp(num / (a * a), -1.0f, 1.0f);
}

// A scattered direction around the unit travel direction `forward`, from uniforms (u1, u2);
// `pdf` receives its solid-angle density, which equals the phase function's value there.
inline glm::vec3 hg_sample(const glm::vec3& forward, float g, float u1, float u2, float& pdf) {
    const float cos_t = hg_sample_cos(g, u1);
    const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
    const float phi = 2.0f * kPi * u2;
    const Frame frame(forward);
    pdf = hg_phase(cos_t, g);
    return glm::normalize(frame.to_world({sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t}));
}

}  // namespace sweeptrace

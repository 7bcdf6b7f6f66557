#pragma once
// The GGX (Trowbridge-Reitz) microfacet distribution shared by the metal, the rough dielectric
// and anything else with a microfacet lobe: its normal distribution D, Smith's Lambda, and
// visible-normal sampling with its density; and Beckmann's D, Lambda and normal sampling, which a
// conductor may choose instead (Material::Microfacet). Local frame: the macro normal is +z, directions unit.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

// GGX normal distribution for a unit half vector h in the local frame, written with
// sin^2/alpha^2 + cos^2 (not 1 + cos^2 (alpha^2 - 1)) to avoid cancellation at small alpha.
inline float ggx_d(const glm::vec3& h, float alpha) {
    const float a2 = alpha * alpha;
    const float e = (h.x * h.x + h.y * h.y) / a2 + h.z * h.z;
    return 1.0f / (kPi * a2 * e * e);
}

// Smith Lambda for GGX; infinite at grazing (so G1 = 0 there). Even in w.z, so it serves
// directions below the macro surface (transmission) too.
inline float ggx_lambda(const glm::vec3& w, float alpha) {
    const float z2 = w.z * w.z;
    if (z2 == 0.0f) return INFINITY;
    const float a2t2 = alpha * alpha * (w.x * w.x + w.y * w.y) / z2;
    return 0.5f * (std::sqrt(1.0f + a2t2) - 1.0f);
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals": a microfacet normal with
// density ggx_vndf_pdf(wo, h) = G1(wo) max(0, wo.h) D(h) / wo.z, for wo.z > 0.
inline glm::vec3 sample_ggx_vndf(const glm::vec3& wo, float alpha, float u1, float u2) {
    const glm::vec3 vh = glm::normalize(glm::vec3(alpha * wo.x, alpha * wo.y, wo.z));
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const glm::vec3 t1 = lensq > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lensq) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u1);
    const float phi = 2.0f * kPi * u2;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(0.0f, nh.z)));
}

// Beckmann's normal distribution (Walter et al. 2007, eq. 25): exp(-tan^2 / alpha^2) over
// pi alpha^2 cos^4. Its tails fall like a Gaussian in the slope, GGX's like 1 / tan^4: at the
// same alpha GGX sends far more light wide of the mirror direction.
inline float beckmann_d(const glm::vec3& h, float alpha) {
    const float c2 = h.z * h.z;
    if (!(c2 > 0.0f)) return 0.0f;
    const float t2 = (h.x * h.x + h.y * h.y) / c2;
    return std::exp(-t2 / (alpha * alpha)) / (kPi * alpha * alpha * c2 * c2);
}

// Smith Lambda for Beckmann, exact (Walter et al. 2007, eq. 27 before its rational fit):
// a = 1 / (alpha tan), Lambda = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)). Even in w.z.
inline float beckmann_lambda(const glm::vec3& w, float alpha) {
    const float s2 = w.x * w.x + w.y * w.y;
    if (s2 == 0.0f) return 0.0f;
    if (w.z == 0.0f) return INFINITY;
    const float a = std::abs(w.z) / (alpha * std::sqrt(s2));
    if (a > 6.0f) return 0.0f;  // erf(6) is 1 in float and exp(-36) negligible
    return std::max(0.0f, 0.5f * (std::erf(a) - 1.0f) + std::exp(-a * a) / (2.0f * a * std::sqrt(kPi)));
}

// A Beckmann microfacet normal with density D(h) h.z (Walter et al. 2007, eq. 28):
// tan^2 = -alpha^2 ln(1 - u1), phi = 2 pi u2.
inline glm::vec3 sample_beckmann_normal(float alpha, float u1, float u2) {
    const float t2 = -alpha * alpha * std::log(std::max(1.0f - u1, 1e-30f));
    const float c = 1.0f / std::sqrt(1.0f + t2);
    const float s = std::sqrt(std::max(0.0f, 1.0f - c * c));
    const float phi = 2.0f * kPi * u2;
    return {s * std::cos(phi), s * std::sin(phi), c};
}

inline float ggx_vndf_pdf(const glm::vec3& wo, const glm::vec3& h, float alpha) {
    const float wo_h = glm::dot(wo, h);
    if (wo_h <= 0.0f || wo.z <= 0.0f) return 0.0f;
    return ggx_d(h, alpha) * wo_h / (wo.z * (1.0f + ggx_lambda(wo, alpha)));
}

}  // namespace sweeptrace

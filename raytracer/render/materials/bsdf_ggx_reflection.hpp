#pragma once
// GGX microfacet reflection, the lobe the metal (Schlick Fresnel, render/materials/bsdf.cpp) and the
// conductor (complex-IOR Fresnel, render/materials/bsdf_conductor.cpp) share: only the Fresnel term differs,
// so the distribution, masking, sampling and density live here once. bsdf.hpp states the model
// (height-correlated Smith G2, visible-normal sampling, alpha = roughness^2 clamped at
// kMinMetalAlpha; roughness 0 a perfect mirror, a delta lobe). `fresnel(cos_d)` returns the RGB
// reflectance at the angle between the light and the microfacet normal. A conductor may choose
// Beckmann's distribution instead (Material::Microfacet): the same alpha and height-correlated G2,
// with its exact Lambda, and normals sampled by D(h) h.z (no visible-normal sampling).
#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/materials/microfacet.hpp"

namespace sweeptrace::ggx_reflection {

inline float alpha(const MaterialParameters& m) { return std::max(m.roughness * m.roughness, kMinMetalAlpha); }

// The conductor may choose Beckmann's distribution (Material::Microfacet); the metal is GGX.
inline bool beckmann(const MaterialParameters& m) { return m.microfacet == Material::Microfacet::Beckmann; }
inline float lobe_d(const MaterialParameters& m, const glm::vec3& h, float a) { return beckmann(m) ? beckmann_d(h, a) : ggx_d(h, a); }
inline float lobe_lambda(const MaterialParameters& m, const glm::vec3& w, float a) {
    return beckmann(m) ? beckmann_lambda(w, a) : ggx_lambda(w, a);
}
// The density of wi: GGX samples visible normals, D G1(wo) / (4 wo.z); Beckmann samples D(h) h.z,
// and the reflection's Jacobian 1 / (4 wo.h) makes it D h.z / (4 wo.h).
inline float lobe_pdf(const MaterialParameters& m, const glm::vec3& wo, const glm::vec3& h, float d, float lambda_o) {
    if (!beckmann(m)) return d / (4.0f * wo.z * (1.0f + lambda_o));
    const float wo_h = glm::dot(wo, h);
    return wo_h > 0.0f ? d * h.z / (4.0f * wo_h) : 0.0f;
}

// Reflection must stay on wo's side of both the shading and the geometric normal.
inline bool valid(const ShadingContext& ctx, const glm::vec3& wi_local, const glm::vec3& wi) {
    return ctx.wo_local.z > 0.0f && wi_local.z > 0.0f && glm::dot(wi, ctx.ng) > 0.0f;
}

template <class Fresnel>
BsdfEval eval(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi, Fresnel fresnel) {
    BsdfEval e;
    if (m.roughness == 0.0f) return e;
    const glm::vec3 wl = ctx.frame.to_local(wi);
    if (!valid(ctx, wl, wi)) return e;
    const glm::vec3& wo = ctx.wo_local;
    const float a = alpha(m);
    const glm::vec3 h = glm::normalize(wo + wl);
    const float d = lobe_d(m, h, a);
    const float lo = lobe_lambda(m, wo, a), li = lobe_lambda(m, wl, a);
    const float g2 = 1.0f / (1.0f + lo + li);
    e.f_cos = fresnel(glm::dot(wl, h)) * (d * g2 / (4.0f * wo.z));
    e.pdf = lobe_pdf(m, wo, h, d, lo);
    return e;
}

template <class Fresnel>
bool sample(const MaterialParameters& m, const ShadingContext& ctx, float u1, float u2, BsdfSample& out, Fresnel fresnel) {
    const glm::vec3& wo = ctx.wo_local;
    if (wo.z <= 0.0f) return false;
    if (m.roughness == 0.0f) {
        const glm::vec3 wl(-wo.x, -wo.y, wo.z);
        const glm::vec3 wi = ctx.frame.to_world(wl);
        if (!valid(ctx, wl, wi)) return false;
        out = BsdfSample{wi, fresnel(wo.z), 1.0f, true};
        return true;
    }
    const float a = alpha(m);
    if (beckmann(m)) {
        const glm::vec3 h = sample_beckmann_normal(a, u1, u2);
        const float wo_h = glm::dot(wo, h);
        if (!(wo_h > 0.0f)) return false;
        const glm::vec3 wl = 2.0f * wo_h * h - wo;
        const glm::vec3 wi = ctx.frame.to_world(wl);
        if (!valid(ctx, wl, wi)) return false;
        const float d = beckmann_d(h, a);
        const float lo = beckmann_lambda(wo, a), li = beckmann_lambda(wl, a);
        // f cos / pdf = F G2 wo.h / (wo.z h.z): D cancels.
        out = BsdfSample{wi, fresnel(wo_h) * (wo_h / (wo.z * h.z * (1.0f + lo + li))), lobe_pdf(m, wo, h, d, lo), false};
        return out.pdf > 0.0f;
    }
    const glm::vec3 h = sample_ggx_vndf(wo, a, u1, u2);
    const float wo_h = glm::dot(wo, h);
    const glm::vec3 wl = 2.0f * wo_h * h - wo;
    const glm::vec3 wi = ctx.frame.to_world(wl);
    if (!valid(ctx, wl, wi)) return false;
    const float lo = ggx_lambda(wo, a), li = ggx_lambda(wl, a);
    // f cos / pdf = F G2 / G1(wo): D and the Jacobian cancel.
    const float g_ratio = (1.0f + lo) / (1.0f + lo + li);
    out = BsdfSample{wi, fresnel(wo_h) * g_ratio, lobe_pdf(m, wo, h, ggx_d(h, a), lo), false};
    return out.pdf > 0.0f;
}

}  // namespace sweeptrace::ggx_reflection

// The rough dielectric interface (bsdf.hpp states the model): GGX reflection and transmission
// after Walter, Marschner, Li and Torrance, "Microfacet Models for Refraction through Rough
// Surfaces" (EGSR 2007), in the form of pbrt-v4's DielectricBxDF. A microfacet normal is drawn
// from wo's visible normals (Heitz 2018, as the metal does); reflection or refraction about it is
// chosen with its exact Fresnel reflectance, so sample and eval share every density:
//   reflection:   pdf = D_wo(h) / (4 |wo.h|) R,              h = normalize(wo + wi)
//   transmission: pdf = D_wo(h) |wi.h| / (wi.h + wo.h/eta)^2 T,  h = normalize(wo + eta wi)
// with D_wo the visible-normal density, R = F(wo.h), T = 1 - R, eta = n(wi side) / n(wo side).
// Weights: G2/G1 for reflection, albedo G2/(G1 eta^2) for transmission (D, F and the Jacobians
// cancel); G2 is the height-correlated Smith term. Single scattering: energy that would bounce
// between microfacets is lost, as for the metal (the furnace tests state how much).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/materials/microfacet.hpp"

namespace sweeptrace {

namespace {

float rough_dielectric_alpha(const MaterialParameters& m) { return std::max(m.roughness * m.roughness, kMinMetalAlpha); }

// n(wi side) / n(wo side) for a transmitted wi: wo in front (outside) means wi inside the medium.
float relative_eta(const MaterialParameters& m, const ShadingContext& ctx) { return ctx.front ? m.ior : 1.0f / m.ior; }

// Refraction of wo about the microfacet normal h (wo.h > 0); false on total internal reflection.
bool refract_about(const glm::vec3& wo, const glm::vec3& h, float eta, glm::vec3& wi) {
    const float cos_o = glm::dot(wo, h);
    const float sin2_t = std::max(0.0f, 1.0f - cos_o * cos_o) / (eta * eta);
    if (sin2_t >= 1.0f) return false;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    wi = glm::normalize(-wo / eta + (cos_o / eta - cos_t) * h);
    return true;
}

// The two lobes' densities and f cos for a given (wo, wi, h), wo.z > 0; shared by eval and sample.
struct RoughLobe {
    float f_cos = 0.0f;  // untinted
    float pdf = 0.0f;
};

RoughLobe rough_lobe(const glm::vec3& wo, const glm::vec3& wi, const glm::vec3& h, float alpha, float eta) {
    RoughLobe lobe;
    const float wo_h = glm::dot(wo, h), wi_h = glm::dot(wi, h);
    const bool reflect = wi.z > 0.0f;
    // Microfacets seen from behind by either direction contribute nothing (Walter's chi+ terms).
    if (wo_h <= 0.0f || (reflect ? wi_h <= 0.0f : wi_h >= 0.0f) || wi.z == 0.0f) return lobe;
    float cos_t = 0.0f;
    const float r = fresnel_dielectric(std::min(wo_h, 1.0f), eta, cos_t);
    const float d = ggx_d(h, alpha);
    const float lo = ggx_lambda(wo, alpha), li = ggx_lambda(wi, alpha);
    const float g2 = 1.0f / (1.0f + lo + li);
    const float vndf = d * wo_h / (wo.z * (1.0f + lo));
    if (reflect) {
        lobe.f_cos = d * g2 * r / (4.0f * wo.z);
        lobe.pdf = vndf / (4.0f * wo_h) * r;
        return lobe;
    }
    const float t = 1.0f - r;
    const float denom = (wi_h + wo_h / eta) * (wi_h + wo_h / eta);
    lobe.f_cos = t * d * g2 * std::abs(wi_h) * wo_h / (denom * wo.z * eta * eta);
    lobe.pdf = vndf * std::abs(wi_h) / denom * t;
    return lobe;
}

}  // namespace

BsdfEval eval_rough_dielectric(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi) {
    BsdfEval e;
    const glm::vec3& wo = ctx.wo_local;
    if (wo.z <= 0.0f) return e;
    const glm::vec3 wl = ctx.frame.to_local(wi);
    const bool reflect = wl.z > 0.0f;
    // Which side wi is on must agree between shading and geometric normal (no light leaks).
    if (reflect != (glm::dot(wi, ctx.ng) > 0.0f)) return e;
    const float eta = relative_eta(m, ctx);
    const glm::vec3 sum = reflect ? wo + wl : wo + eta * wl;
    const float len2 = glm::dot(sum, sum);
    if (!(len2 > 0.0f)) return e;
    glm::vec3 h = sum / std::sqrt(len2);
    if (h.z < 0.0f) h = -h;
    const RoughLobe lobe = rough_lobe(wo, wl, h, rough_dielectric_alpha(m), eta);
    e.f_cos = (reflect ? glm::vec3(1.0f) : m.albedo) * lobe.f_cos;
    e.pdf = lobe.pdf;
    return e;
}

bool sample_rough_dielectric(const MaterialParameters& m, const ShadingContext& ctx, float u0, float u1, float u2,
                             BsdfSample& out) {
    const glm::vec3& wo = ctx.wo_local;
    if (wo.z <= 0.0f) return false;
    const float alpha = rough_dielectric_alpha(m);
    const float eta = relative_eta(m, ctx);
    const glm::vec3 h = sample_ggx_vndf(wo, alpha, u1, u2);
    const float wo_h = glm::dot(wo, h);
    if (wo_h <= 0.0f) return false;
    float cos_t = 0.0f;
    const float r = fresnel_dielectric(std::min(wo_h, 1.0f), eta, cos_t);
    glm::vec3 wl;
    const bool reflect = u0 < r;
    if (reflect) {
        wl = 2.0f * wo_h * h - wo;
        if (wl.z <= 0.0f) return false;
    } else if (!refract_about(wo, h, eta, wl) || wl.z >= 0.0f) {
        return false;
    }
    const glm::vec3 wi = ctx.frame.to_world(wl);
    if (reflect != (glm::dot(wi, ctx.ng) > 0.0f)) return false;
    // Density and weight from the same expressions eval uses, at the sampled h (not the one
    // recomputed from wi, which differs by rounding only).
    const RoughLobe lobe = rough_lobe(wo, wl, h, alpha, eta);
    if (!(lobe.pdf > 0.0f)) return false;
    const float lo = ggx_lambda(wo, alpha), li = ggx_lambda(wl, alpha);
    const float g_ratio = (1.0f + lo) / (1.0f + lo + li);
    out = BsdfSample{wi, reflect ? glm::vec3(g_ratio) : m.albedo * (g_ratio / (eta * eta)), lobe.pdf, false};
    return true;
}

}  // namespace sweeptrace

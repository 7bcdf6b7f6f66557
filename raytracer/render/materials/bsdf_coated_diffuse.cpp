// The coated diffuse material, "plastic" (bsdf.hpp states the model). The diffuse term follows
// from summing the light's round trips inside the coating: light from wi enters with 1 - F_i and
// meets the base; the base sends back L_d = rho E / pi, diffuse; of that the interface returns
// the share Fint to the base again (so E = E_in + pi L_d Fint, a geometric series) and lets
// (1 - F_o) L_d / eta^2 out toward wo. Solving: L_d = rho E_in / (pi (1 - rho Fint)).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/materials/coat_albedo.hpp"
#include "raytracer/render/materials/microfacet.hpp"
#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

float fresnel_diffuse_reflectance(float eta) {
    // Simpson's rule on [0, 1] in mu = cos theta. For eta >= 1 the integrand 2 mu F(mu) is smooth
    // (no critical angle entering the denser medium); 64 intervals leave an error below 1e-7
    // (checked against a long-double adaptive integral in test_render_coated_diffuse.cpp).
    thread_local float cached_eta = -1.0f, cached = 0.0f;
    if (eta == cached_eta) return cached;
    constexpr int n = 64;
    double sum = 0.0;
    for (int k = 0; k <= n; ++k) {
        const float mu = static_cast<float>(k) / n;
        float cos_t = 0.0f;
        const double f = fresnel_dielectric(mu, eta, cos_t);
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
        sum += w * 2.0 * mu * f;
    }
    cached_eta = eta;
    cached = static_cast<float>(sum / (3.0 * n));
    return cached;
}

namespace {

// What both lobes need from wo. The coat's reflectance e is F(cos) for the smooth coat and the
// rough lobe's albedo E(cos) (render/materials/coat_albedo.hpp) for a rough one; e_mean its mean.
struct CoatedTerms {
    float e_o = 0.0f;           // the coat's reflectance toward wo
    glm::vec3 diffuse{0.0f};    // f_d = diffuse (1 - e_i)(1 - e_o)
    float p_specular = 1.0f;    // probability of sampling the coat's lobe
};

float coat_reflectance(const MaterialParameters& m, float cos_theta) {
    const float mu = std::clamp(cos_theta, 0.0f, 1.0f);
    if (m.roughness > 0.0f) return coat_albedo(m.ior, m.roughness, mu).albedo;
    float cos_t = 0.0f;
    return fresnel_dielectric(mu, m.ior, cos_t);
}

CoatedTerms coated_terms(const MaterialParameters& m, float cos_o) {
    CoatedTerms c;
    const float eta = m.ior;
    c.e_o = coat_reflectance(m, cos_o);
    const float f_ext = fresnel_diffuse_reflectance(eta);
    const float f_int = 1.0f - (1.0f - f_ext) / (eta * eta);
    const float e_mean = m.roughness > 0.0f ? coat_albedo(eta, m.roughness, cos_o).mean_albedo : f_ext;
    const glm::vec3 base = m.albedo * (1.0f - f_int) / (glm::vec3(1.0f) - m.albedo * f_int);
    c.diffuse = base / (kPi * (1.0f - e_mean));
    // The diffuse lobe's directional albedo, (1 - e_o) rho (1 - Fint) / (1 - rho Fint), decides
    // how often it is sampled against the coat's e_o.
    const float a_d = luminance((1.0f - c.e_o) * base);
    c.p_specular = c.e_o + a_d > 0.0f ? c.e_o / (c.e_o + a_d) : 1.0f;
    return c;
}

bool reflects(const ShadingContext& ctx, const glm::vec3& wl, const glm::vec3& wi) {
    return ctx.wo_local.z > 0.0f && wl.z > 0.0f && glm::dot(wi, ctx.ng) > 0.0f;
}

// The rough coat's GGX reflection: f cos and the visible-normal density of sampling wl.
BsdfEval rough_coat_lobe(const MaterialParameters& m, const glm::vec3& wo, const glm::vec3& wl) {
    BsdfEval e;
    const glm::vec3 h = glm::normalize(wo + wl);
    const float wo_h = glm::dot(wo, h);
    if (!(wo_h > 0.0f)) return e;
    const float alpha = coat_alpha(m.roughness);
    const float d = ggx_d(h, alpha), lo = ggx_lambda(wo, alpha), li = ggx_lambda(wl, alpha);
    float cos_t = 0.0f;
    const float f = fresnel_dielectric(std::min(wo_h, 1.0f), m.ior, cos_t);
    e.f_cos = glm::vec3(d * f / (4.0f * wo.z * (1.0f + lo + li)));
    e.pdf = d / (4.0f * wo.z * (1.0f + lo));
    return e;
}

}  // namespace

BsdfEval eval_coated_diffuse(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi) {
    BsdfEval e;
    const glm::vec3 wl = ctx.frame.to_local(wi);
    if (!reflects(ctx, wl, wi)) return e;
    const CoatedTerms c = coated_terms(m, ctx.wo_local.z);
    const float e_i = coat_reflectance(m, wl.z);
    e.f_cos = c.diffuse * ((1.0f - e_i) * (1.0f - c.e_o) * wl.z);
    e.pdf = (1.0f - c.p_specular) * kInvPi * wl.z;
    if (m.roughness > 0.0f) {  // the coat's lobe joins the mixture; a smooth coat's is a delta
        const BsdfEval spec = rough_coat_lobe(m, ctx.wo_local, wl);
        e.f_cos += spec.f_cos;
        e.pdf += c.p_specular * spec.pdf;
    }
    return e;
}

bool sample_coated_diffuse(const MaterialParameters& m, const ShadingContext& ctx, float u0, float u1, float u2,
                           BsdfSample& out) {
    const glm::vec3& wo = ctx.wo_local;
    if (wo.z <= 0.0f) return false;
    const CoatedTerms c = coated_terms(m, wo.z);
    const bool coat = u0 < c.p_specular;
    if (coat && m.roughness == 0.0f) {
        const glm::vec3 wl(-wo.x, -wo.y, wo.z);
        const glm::vec3 wi = ctx.frame.to_world(wl);
        if (!reflects(ctx, wl, wi)) return false;
        out = BsdfSample{wi, glm::vec3(c.e_o / c.p_specular), c.p_specular, true};
        return true;
    }
    glm::vec3 wl = cosine_hemisphere(u1, u2);
    if (coat) {
        const glm::vec3 h = sample_ggx_vndf(wo, coat_alpha(m.roughness), u1, u2);
        wl = 2.0f * glm::dot(wo, h) * h - wo;
    }
    const glm::vec3 wi = ctx.frame.to_world(wl);
    if (!reflects(ctx, wl, wi)) return false;
    // Both lobes are non-delta here (or only the diffuse one is sampled): the weight is the whole
    // f cos over the mixture density, the same numbers eval_coated_diffuse returns for wi.
    const BsdfEval e = eval_coated_diffuse(m, ctx, wi);
    if (!(e.pdf > 0.0f)) return false;
    out = BsdfSample{wi, e.f_cos / e.pdf, e.pdf, false};
    return true;
}

}  // namespace sweeptrace

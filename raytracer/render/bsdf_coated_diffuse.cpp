// The coated diffuse material, "plastic" (bsdf.hpp states the model). The diffuse term follows
// from summing the light's round trips inside the coating: light from wi enters with 1 - F_i and
// meets the base; the base sends back L_d = rho E / pi, diffuse; of that the interface returns
// the share Fint to the base again (so E = E_in + pi L_d Fint, a geometric series) and lets
// (1 - F_o) L_d / eta^2 out toward wo. Solving: L_d = rho E_in / (pi (1 - rho Fint)).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/render/bsdf.hpp"
#include "raytracer/render/sampling.hpp"

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

struct CoatedTerms {
    float f_o = 0.0f;           // coating reflectance toward wo
    glm::vec3 diffuse{0.0f};    // rho / (pi eta^2 (1 - rho Fint)): f = diffuse (1 - F_i)(1 - F_o)
    float p_specular = 1.0f;    // probability of sampling the mirror lobe
};

CoatedTerms coated_terms(const Material& m, float cos_o) {
    CoatedTerms c;
    const float eta = m.ior;
    float cos_t = 0.0f;
    c.f_o = fresnel_dielectric(std::clamp(cos_o, 0.0f, 1.0f), eta, cos_t);
    const float f_int = 1.0f - (1.0f - fresnel_diffuse_reflectance(eta)) / (eta * eta);
    const glm::vec3 denom = glm::vec3(1.0f) - m.albedo * f_int;
    c.diffuse = m.albedo / (kPi * eta * eta * denom);
    // The diffuse lobe's directional albedo, (1 - F_o) rho (1 - Fint) / (1 - rho Fint), decides
    // how often it is sampled against the mirror's F_o.
    const float a_d = luminance((1.0f - c.f_o) * m.albedo * (1.0f - f_int) / denom);
    c.p_specular = c.f_o + a_d > 0.0f ? c.f_o / (c.f_o + a_d) : 1.0f;
    return c;
}

bool reflects(const ShadingContext& ctx, const glm::vec3& wl, const glm::vec3& wi) {
    return ctx.wo_local.z > 0.0f && wl.z > 0.0f && glm::dot(wi, ctx.ng) > 0.0f;
}

}  // namespace

BsdfEval eval_coated_diffuse(const Material& m, const ShadingContext& ctx, const glm::vec3& wi) {
    BsdfEval e;
    const glm::vec3 wl = ctx.frame.to_local(wi);
    if (!reflects(ctx, wl, wi)) return e;
    const CoatedTerms c = coated_terms(m, ctx.wo_local.z);
    float cos_t = 0.0f;
    const float f_i = fresnel_dielectric(std::min(wl.z, 1.0f), m.ior, cos_t);
    e.f_cos = c.diffuse * ((1.0f - f_i) * (1.0f - c.f_o) * wl.z);
    e.pdf = (1.0f - c.p_specular) * kInvPi * wl.z;
    return e;
}

bool sample_coated_diffuse(const Material& m, const ShadingContext& ctx, float u0, float u1, float u2,
                           BsdfSample& out) {
    const glm::vec3& wo = ctx.wo_local;
    if (wo.z <= 0.0f) return false;
    const CoatedTerms c = coated_terms(m, wo.z);
    if (u0 < c.p_specular) {
        const glm::vec3 wl(-wo.x, -wo.y, wo.z);
        const glm::vec3 wi = ctx.frame.to_world(wl);
        if (!reflects(ctx, wl, wi)) return false;
        out = BsdfSample{wi, glm::vec3(c.f_o / c.p_specular), c.p_specular, true};
        return true;
    }
    const glm::vec3 wl = cosine_hemisphere(u1, u2);
    const glm::vec3 wi = ctx.frame.to_world(wl);
    if (!reflects(ctx, wl, wi)) return false;
    float cos_t = 0.0f;
    const float f_i = fresnel_dielectric(std::min(wl.z, 1.0f), m.ior, cos_t);
    const float pdf = (1.0f - c.p_specular) * kInvPi * wl.z;
    if (!(pdf > 0.0f)) return false;
    // f cos / pdf: the cosines and 1/pi cancel.
    out = BsdfSample{wi, c.diffuse * (kPi * (1.0f - f_i) * (1.0f - c.f_o) / (1.0f - c.p_specular)), pdf, false};
    return true;
}

}  // namespace sweeptrace

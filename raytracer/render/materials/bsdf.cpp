#include "raytracer/render/materials/bsdf.hpp"

#include <algorithm>
#include <cmath>

#include "raytracer/render/materials/bsdf_ggx_reflection.hpp"

namespace sweeptrace {

ShadingContext make_shading_context(const SurfaceHit& hit, const glm::vec3& wo) {
    const bool front = glm::dot(wo, hit.normal) >= 0.0f;
    const float side = front ? 1.0f : -1.0f;
    ShadingContext ctx{Frame(side * hit.shading_normal), side * hit.normal, glm::vec3(0.0f), front};
    ctx.wo_local = ctx.frame.to_local(wo);
    return ctx;
}

bool is_delta(const MaterialParameters& m) {
    return m.type == Material::Type::Dielectric || m.type == Material::Type::ThinDielectric ||
           ((m.type == Material::Type::Metal || m.type == Material::Type::Conductor) && m.roughness == 0.0f) ||
           (m.type == Material::Type::RoughDielectric && rough_dielectric_is_smooth(m));
}

float fresnel_dielectric(float cos_i, float eta, float& cos_t) {
    const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) {
        cos_t = 0.0f;
        return 1.0f;
    }
    cos_t = std::sqrt(1.0f - sin2_t);
    const float r_par = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_par * r_par + r_perp * r_perp);
}

namespace {

glm::vec3 schlick(const glm::vec3& f0, float cos_d) {
    const float m = std::clamp(1.0f - cos_d, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (glm::vec3(1.0f) - f0) * (m2 * m2 * m);
}

using ggx_reflection::valid;

float max3(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// Diffuse: the probability of sampling the transmitted lobe, in proportion to the two lobes'
// largest channels; exactly 0 for an opaque surface, whose sampling (and random stream) is then
// the plain Lambertian's.
float diffuse_transmit_probability(const MaterialParameters& m) {
    const float t = max3(m.transmittance);
    return t > 0.0f ? t / (t + max3(m.albedo)) : 0.0f;
}

bool sample_smooth_dielectric(const MaterialParameters& m, const ShadingContext& ctx, float u0, BsdfSample& out) {
    const glm::vec3& wo = ctx.wo_local;
    if (wo.z <= 0.0f) return false;
    // eta = n_transmitted / n_incident: entering from the front means going into the medium.
    const float eta = ctx.front ? m.ior : 1.0f / m.ior;
    float cos_t = 0.0f;
    const float f = fresnel_dielectric(std::min(wo.z, 1.0f), eta, cos_t);
    if (u0 < f) {
        const glm::vec3 wl(-wo.x, -wo.y, wo.z);
        const glm::vec3 wi = ctx.frame.to_world(wl);
        if (glm::dot(wi, ctx.ng) <= 0.0f) return false;
        out = BsdfSample{wi, glm::vec3(1.0f), f, true};
        return true;
    }
    const glm::vec3 wl(-wo.x / eta, -wo.y / eta, -cos_t);
    const glm::vec3 wi = glm::normalize(ctx.frame.to_world(wl));
    if (glm::dot(wi, ctx.ng) >= 0.0f) return false;
    out = BsdfSample{wi, m.albedo / (eta * eta), 1.0f - f, true};
    return true;
}

}  // namespace

BsdfEval eval_bsdf(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi) {
    BsdfEval e;
    switch (m.type) {
        case Material::Type::Diffuse: {
            const glm::vec3 wl = ctx.frame.to_local(wi);
            const float pt = diffuse_transmit_probability(m);
            if (valid(ctx, wl, wi)) {
                e.f_cos = m.albedo * (kInvPi * wl.z);
                e.pdf = (1.0f - pt) * kInvPi * wl.z;
            } else if (pt > 0.0f && ctx.wo_local.z > 0.0f && wl.z < 0.0f && glm::dot(wi, ctx.ng) < 0.0f) {
                // Transmission: wi on the far side of both the shading and the geometric normal.
                e.f_cos = m.transmittance * (kInvPi * -wl.z);
                e.pdf = pt * kInvPi * -wl.z;
            }
            return e;
        }
        case Material::Type::Metal:
            return ggx_reflection::eval(m, ctx, wi, [&](float cos_d) { return schlick(m.albedo, cos_d); });
        case Material::Type::Conductor:
            return eval_conductor(m, ctx, wi);
        case Material::Type::RoughDielectric:
            return rough_dielectric_is_smooth(m) ? e : eval_rough_dielectric(m, ctx, wi);
        case Material::Type::CoatedDiffuse:
            return eval_coated_diffuse(m, ctx, wi);
        case Material::Type::Dielectric:
        case Material::Type::ThinDielectric:
        case Material::Type::Emissive:
        case Material::Type::Interface:  // no surface for light: the integrator passes through it
            return e;
    }
    return e;
}

bool sample_bsdf(const MaterialParameters& m, const ShadingContext& ctx, float u0, float u1, float u2, BsdfSample& out) {
    switch (m.type) {
        case Material::Type::Diffuse: {
            const float pt = diffuse_transmit_probability(m);
            if (pt > 0.0f && u0 < pt) {
                if (ctx.wo_local.z <= 0.0f) return false;
                glm::vec3 wl = cosine_hemisphere(u1, u2);
                wl.z = -wl.z;
                const glm::vec3 wi = ctx.frame.to_world(wl);
                if (glm::dot(wi, ctx.ng) >= 0.0f) return false;
                out = BsdfSample{wi, m.transmittance / pt, pt * kInvPi * -wl.z, false};
                return out.pdf > 0.0f;
            }
            const glm::vec3 wl = cosine_hemisphere(u1, u2);
            const glm::vec3 wi = ctx.frame.to_world(wl);
            if (!valid(ctx, wl, wi)) return false;
            out = BsdfSample{wi, pt > 0.0f ? m.albedo / (1.0f - pt) : m.albedo, (1.0f - pt) * kInvPi * wl.z, false};
            return out.pdf > 0.0f;
        }
        case Material::Type::Metal:
            return ggx_reflection::sample(m, ctx, u1, u2, out, [&](float cos_d) { return schlick(m.albedo, cos_d); });
        case Material::Type::Conductor:
            return sample_conductor(m, ctx, u1, u2, out);
        case Material::Type::Dielectric:
            return sample_smooth_dielectric(m, ctx, u0, out);
        case Material::Type::ThinDielectric:
            return sample_thin_dielectric(m, ctx, u0, out);
        case Material::Type::RoughDielectric:
            return rough_dielectric_is_smooth(m) ? sample_smooth_dielectric(m, ctx, u0, out)
                                                 : sample_rough_dielectric(m, ctx, u0, u1, u2, out);
        case Material::Type::CoatedDiffuse:
            return sample_coated_diffuse(m, ctx, u0, u1, u2, out);
        case Material::Type::Emissive:
        case Material::Type::Interface:
            return false;
    }
    return false;
}

BsdfEvalBoth eval_bsdf_both(const MaterialParameters& m, const SurfaceHit& hit, const glm::vec3& wo, const glm::vec3& wi) {
    const BsdfEval e = eval_bsdf(m, make_shading_context(hit, wo), wi);
    BsdfEvalBoth both{e.f_cos, e.pdf, 0.0f};
    if (e.pdf > 0.0f) both.pdf_wo = eval_bsdf(m, make_shading_context(hit, wi), wo).pdf;
    return both;
}

float importance_refraction_scale(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi) {
    if (m.type != Material::Type::Dielectric && m.type != Material::Type::RoughDielectric) return 1.0f;
    if (glm::dot(wi, ctx.ng) >= 0.0f) return 1.0f;  // reflected
    const float eta = ctx.front ? m.ior : 1.0f / m.ior;
    return eta * eta;
}

}  // namespace sweeptrace

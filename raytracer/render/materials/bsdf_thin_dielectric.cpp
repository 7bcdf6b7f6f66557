// The thin dielectric sheet (bsdf.hpp states the model).
#include <algorithm>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"

namespace sweeptrace {

float thin_dielectric_reflectance(float cos_i, float ior) {
    float cos_t = 0.0f;
    const float r = fresnel_dielectric(std::clamp(cos_i, 0.0f, 1.0f), ior, cos_t);
    if (r >= 1.0f) return 1.0f;  // only for ior < 1 past its critical angle
    const float t = 1.0f - r;
    return r + t * t * r / (1.0f - r * r);
}

bool sample_thin_dielectric(const MaterialParameters& m, const ShadingContext& ctx, float u0, BsdfSample& out) {
    const glm::vec3& wo = ctx.wo_local;
    if (wo.z <= 0.0f) return false;
    // The same sheet from either side: entering from the front or the back is the same ior.
    const float r = thin_dielectric_reflectance(wo.z, m.ior);
    if (u0 < r) {
        const glm::vec3 wi = ctx.frame.to_world(glm::vec3(-wo.x, -wo.y, wo.z));
        if (glm::dot(wi, ctx.ng) <= 0.0f) return false;
        out = BsdfSample{wi, glm::vec3(1.0f), r, true};
        return true;
    }
    const glm::vec3 wi = -ctx.frame.to_world(wo);  // straight through
    if (glm::dot(wi, ctx.ng) >= 0.0f) return false;
    out = BsdfSample{wi, m.albedo, 1.0f - r, true};
    return true;
}

}  // namespace sweeptrace

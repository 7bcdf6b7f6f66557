#pragma once
// Scattering by the scene's materials. One switch on Material::Type per call, no virtual dispatch
// and no allocation.
//
// Conventions: directions are unit vectors pointing away from the surface (wo toward where the
// light goes, wi toward where it comes from). Lobes are evaluated in a frame around the shading
// normal turned to wo's side of the geometric normal; reflection additionally requires wi on
// wo's side of the *geometric* normal and transmission the other side, so interpolated normals
// never let light leak through a surface.
//
// - Diffuse: Lambert, f = albedo / pi, cosine-weighted sampling; with a transmittance T (pbrt-v4's
//   diffusetransmission) also f = T / pi on the far side (wi behind both normals), the side
//   chosen with probability in proportion to max(albedo) and max(T), then cosine-weighted.
// - Metal: GGX (Trowbridge-Reitz) microfacet reflection with height-correlated Smith masking,
//   Schlick Fresnel with F0 = albedo, visible-normal sampling (Heitz 2018), alpha = roughness^2
//   clamped below at kMinMetalAlpha. Single scattering only: very rough metal loses the energy of
//   multiple bounces between microfacets, as in pbrt-v3: measured (test_render_metal_energy.cpp)
//   ~1% at roughness 0.3, ~18% at 0.6 and ~69% at 1 head-on (alpha 1; a numerical integral of
//   the model gives the same 0.307 albedo), less toward grazing.
//   roughness == 0 is a perfect mirror (a delta lobe).
// - Conductor: the metal's GGX lobe (render/materials/bsdf_ggx_reflection.hpp, the same alpha and losses)
//   with the exact Fresnel reflectance of a complex index of refraction eta + i k per RGB channel
//   (fresnel_conductor below) in place of Schlick's, times albedo (a tint, 1 unless given).
//   roughness == 0 is a perfect mirror of weight albedo F(cos theta_o) (delta).
// - Dielectric: smooth interface, exact Fresnel for unpolarised light, reflection or refraction
//   chosen with probability F (total internal reflection when no refracted direction exists),
//   inside/outside decided by the geometric normal. Refraction is tinted by albedo and scales
//   radiance by 1/eta^2 (radiance is not conserved across a refractive boundary, pbrt §16.1).
// - Rough dielectric: GGX microfacet reflection and refraction (Walter et al. 2007), the
//   microfacet normal drawn from wo's visible normals like the metal, reflection or refraction
//   about it chosen with its exact Fresnel reflectance; alpha = roughness^2 clamped like the
//   metal's, refraction tinted by albedo and scaled by 1/eta^2 like the smooth dielectric.
//   Single scattering (rough glass loses energy; the furnace tests state how much).
//   roughness == 0 (or ior == 1) is the smooth dielectric, a delta lobe
//   (render/materials/bsdf_rough_dielectric.cpp).
// - Coated diffuse ("plastic"): a dielectric coat of index ior over a Lambertian base of albedo
//   rho, the layer thin and clear. An analytic layered model (render/materials/bsdf_coated_diffuse.cpp
//   derives it): the coat's own reflection lobe plus a diffuse lobe
//     f_d = rho (1 - Fint) (1 - e(cos_i)) (1 - e(cos_o)) / (pi (1 - e_mean) (1 - rho Fint)),
//   e(cos) the coat's directional reflectance, e_mean = int_0^1 2 mu e(mu) dmu its mean, and
//   Fint = 1 - (1 - Fext) / eta^2 the interface's cosine-weighted mean reflectance seen from
//   inside (Fext = int_0^1 2 mu F(mu) dmu from outside). Smooth coat (roughness 0): e = F, the
//   coat lobe a mirror of weight F(cos_o) (delta, sampled but never evaluated), and f_d is then
//   exact for a thin clear layer: rho (1 - F_i)(1 - F_o) / (pi eta^2 (1 - rho Fint)). Rough coat:
//   the coat lobe is GGX reflection with exact Fresnel (alpha = roughness^2, as the metal's) and
//   e its tabulated albedo (render/materials/coat_albedo.hpp), in the manner of Kelemen and Szirmay-Kalos
//   (2001); Fint keeps the smooth interface's value, an approximation that only shades how much
//   a dark base darkens. Either way f is symmetric in wi and wo (reciprocal), and its directional
//   albedo is e_o + (1 - e_o) rho (1 - Fint) / (1 - rho Fint) <= 1 (the coat lobe's true albedo
//   in place of e_o: the table errs only upward), 1 when rho = 1 and the coat is smooth.
// - Emissive: a pure emitter, black (absorbs everything it does not emit).
// Emission itself is not part of the BSDF; see emitted_radiance().
#include <glm/vec3.hpp>

#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// Narrower lobes than alpha = 1e-3 (about 0.06 degrees) are not resolved by any pixel; the clamp
// keeps GGX's 1/alpha^2 peak and tan^2/alpha^2 terms far inside float range.
inline constexpr float kMinMetalAlpha = 1e-3f;

struct ShadingContext {
    Frame frame;         // around the shading normal, on wo's side of the geometric normal
    glm::vec3 ng;        // geometric normal on wo's side
    glm::vec3 wo_local;  // wo in `frame`
    bool front = true;   // wo is on the outward (front) side of the geometric normal
};

ShadingContext make_shading_context(const SurfaceHit& hit, const glm::vec3& wo);

struct BsdfEval {
    glm::vec3 f_cos{0.0f};  // f(wo, wi) |cos theta_i|
    float pdf = 0.0f;       // solid-angle density of sample_bsdf producing wi
};

struct BsdfSample {
    glm::vec3 wi{0.0f};
    glm::vec3 weight{0.0f};  // f |cos theta_i| / pdf (for delta lobes: the lobe's weight)
    float pdf = 0.0f;        // solid-angle density; for delta lobes the discrete probability
    bool delta = false;
};

// True when the material scatters only into isolated directions (no light sampling possible).
bool is_delta(const MaterialParameters& m);
// False for materials that absorb everything (the path ends there).
inline bool scatters(const MaterialParameters& m) { return m.type != Material::Type::Emissive; }

// Zero (and pdf 0) for delta lobes and for wi that the material cannot scatter into.
BsdfEval eval_bsdf(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi);

// Returns false when no direction was produced (absorbed, or the sample fell below the surface).
bool sample_bsdf(const MaterialParameters& m, const ShadingContext& ctx, float u0, float u1, float u2, BsdfSample& out);

// Both directions' densities at a path vertex, for bidirectional methods whose MIS weights ask
// how likely each neighbour was to be sampled from the other side: f |cos theta_i| (the shading
// cosine of wi) for light arriving along wi and leaving along wo, the density of sample_bsdf
// producing wi from wo (pdf_wi) and of producing wo from wi (pdf_wo). Zero for delta lobes.
struct BsdfEvalBoth {
    glm::vec3 f_cos{0.0f};
    float pdf_wi = 0.0f;
    float pdf_wo = 0.0f;
};
BsdfEvalBoth eval_bsdf_both(const MaterialParameters& m, const SurfaceHit& hit, const glm::vec3& wo, const glm::vec3& wi);

// Transporting importance (a light subpath: wo toward the light, wi toward the camera side), a
// refraction carries power, not radiance: the 1/eta^2 that eval_bsdf / sample_bsdf give a
// transmission from wo's side is undone by this factor (eta^2; 1 for reflection and for
// materials that do not bend light; pbrt-v4's TransportMode::Importance).
float importance_refraction_scale(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi);

// Radiance the material emits from a point with outward geometric normal `n` toward `w`
// (unit, pointing away from the surface). Front side only unless Material::two_sided_emission.
inline glm::vec3 emitted_radiance(const MaterialParameters& m, const glm::vec3& n, const glm::vec3& w) {
    const float c = glm::dot(n, w);
    return (c > 0.0f || (m.two_sided_emission && c < 0.0f)) ? m.emission : glm::vec3(0.0f);
}

// Exact Fresnel reflectance of a smooth dielectric interface for unpolarised light.
// cos_i in [0, 1] on the incident side, eta = n_transmitted / n_incident. Returns 1 on total
// internal reflection and writes cos_t (the refracted cosine, >= 0) otherwise.
float fresnel_dielectric(float cos_i, float eta, float& cos_t);

// Exact Fresnel reflectance, for unpolarised light, of a conductor of complex relative index
// n = eta + i k (eta > 0, k >= 0; k = 0 is a dielectric, total internal reflection included), lit
// at cos_i in [0, 1] (clamped). render/materials/bsdf_conductor.cpp derives the closed form; normal
// incidence gives ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2), grazing 1. Relative error against a
// long-double evaluation of the complex formula below 2e-6 (test_render_conductor.cpp).
float fresnel_conductor(float cos_i, float eta, float k);
glm::vec3 fresnel_conductor(float cos_i, const glm::vec3& eta, const glm::vec3& k);

// A thin dielectric sheet (pbrt-v4's ThinDielectricBxDF): two parallel smooth interfaces of
// index ior, the light bouncing between them summed in closed form. With R the single
// interface's Fresnel reflectance at cos_i and T = 1 - R, the sheet reflects
//   R' = R + T^2 R (1 + R^2 + R^4 + ...) = R + T^2 R / (1 - R^2)
// and transmits T' = 1 - R' straight through (the two refractions cancel), tinted by albedo;
// nothing is absorbed, so with albedo 1 the weights sum to exactly 1 at every angle. Two-sided,
// delta in both lobes.
float thin_dielectric_reflectance(float cos_i, float ior);
bool sample_thin_dielectric(const MaterialParameters& m, const ShadingContext& ctx, float u0, BsdfSample& out);

// A rough dielectric of roughness 0 is the smooth one; so is one of ior 1, an index-matched
// interface that bends nothing (every microfacet passes light straight on: a delta lobe, where
// the microfacet transmission's Jacobian would divide by zero).
inline bool rough_dielectric_is_smooth(const MaterialParameters& m) { return m.roughness == 0.0f || m.ior == 1.0f; }

// The conductor, the rough dielectric (not smooth, above) and the coated diffuse; eval_bsdf /
// sample_bsdf dispatch here.
BsdfEval eval_conductor(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi);
bool sample_conductor(const MaterialParameters& m, const ShadingContext& ctx, float u1, float u2, BsdfSample& out);
BsdfEval eval_rough_dielectric(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi);
bool sample_rough_dielectric(const MaterialParameters& m, const ShadingContext& ctx, float u0, float u1, float u2,
                             BsdfSample& out);
BsdfEval eval_coated_diffuse(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi);
bool sample_coated_diffuse(const MaterialParameters& m, const ShadingContext& ctx, float u0, float u1, float u2,
                           BsdfSample& out);
// Fext above: the cosine-weighted hemispherical mean of fresnel_dielectric(mu, eta), eta >= 1.
float fresnel_diffuse_reflectance(float eta);

}  // namespace sweeptrace

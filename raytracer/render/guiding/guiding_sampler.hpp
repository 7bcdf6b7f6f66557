#pragma once
// Guided direction sampling: a one-sample mixture of the BSDF's own sampling and the learned
// incident-radiance distribution (Müller, Gross, Novák 2017, §5, with its fixed BSDF sampling
// fraction of 1/2). With probability kBsdfFraction the BSDF samples, otherwise the guide does;
// either way the direction's density is the mixture's,
//     p(wi) = a p_bsdf(wi) + (1 - a) p_guide(wi),
// and that p is what the sample's weight divides by and what MIS against next event estimation
// uses for the BSDF strategy (guided_pdf), so the estimator stays unbiased wherever the BSDF's
// own density covers the integrand, whatever the guide learned.
//
// Guided materials: diffuse only. Glossy lobes are narrower than the guide's cells at the depths
// it learns in a few passes, so mixing would mostly dilute good BSDF samples; delta lobes cannot
// be guided at all.
#include <glm/vec3.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/guiding/guiding_quadtree.hpp"

namespace sweeptrace {

inline constexpr float kBsdfFraction = 0.5f;

inline bool is_guided(const MaterialParameters& m) { return m.type == Material::Type::Diffuse; }

// The mixture density for wi given the BSDF's density there.
inline float guided_pdf(const DirectionalQuadtree& guide, float bsdf_pdf, const glm::vec3& wi) {
    return kBsdfFraction * bsdf_pdf + (1.0f - kBsdfFraction) * guide.pdf(wi);
}

// Draws from the mixture: u_select picks the strategy, (u0, u1, u2) feed it. Returns false when
// no direction was produced or the BSDF is zero there (the guide may point below the surface).
// `bsdf_pdf` gets the BSDF's own density of the direction (out.pdf is the mixture's).
bool sample_guided(const MaterialParameters& m, const ShadingContext& ctx, const DirectionalQuadtree& guide, float u_select,
                   float u0, float u1, float u2, BsdfSample& out, float& bsdf_pdf);

}  // namespace sweeptrace

#pragma once
// Next event estimation of a sky without a portal, guided by what it learned. A uniform colour or
// the horizon-to-zenith sky with no portal is no light for next event estimation in general
// (drawn uniformly over the sphere it finds a window no more often than cosine-weighted BSDF
// sampling does, and costs a shadow ray: docs/sky-and-portals.md). Where path guiding runs, each
// guiding leaf also learns where the sky is seen from its region: a directional quadtree over the
// sphere, trained on the sky's MIS-weighted estimates L cos / density, from next event samples
// of the sky and from BSDF-sampled rays that escaped to it (so that the first pass, which has no
// sky samples, teaches it too). At a vertex whose leaf learned it, the sky becomes one more light
// for next event estimation (LightSet::sample with the guide), its direction drawn from a
// defensive mixture: with probability kSkyUniformFraction uniform over the sphere, otherwise from
// the learned quadtree. Its density, the mixture's, is what both next event estimation and the
// MIS weight of an escaped BSDF-sampled ray from that vertex use (LightSet::pdf,
// LightSet::guided_sky_weight): the strategies at a vertex are a choice of where the vertex lies,
// so any rule for it keeps the estimator unbiased as long as both sides of MIS read the same
// guide. The uniform part keeps a non-zero density wherever the sky shines, whatever the guide
// missed. Where nothing was learned (the first pass, guiding off, bdpt and vcm) the sky stays
// BSDF sampling's alone, as before.
#include <algorithm>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raytracer/geometry/warps.hpp"
#include "raytracer/render/guiding/guiding_quadtree.hpp"

namespace sweeptrace {

// The uniform part's share. Measured on scenes/sky-window.json without its portal (10 CPU s, seeds
// 7 and 8): 0.1 and 0.5 gave no lower RMSE than 0.25, light_guide.hpp's share for the same role.
inline constexpr float kSkyUniformFraction = 0.25f;

// The mixture's solid-angle density where the learned quadtree's density is `learned`.
inline float sky_mixture_density(float learned) {
    return kSkyUniformFraction * (0.25f * kInvPi) + (1.0f - kSkyUniformFraction) * learned;
}

// The mixture's density of unit direction `dir`.
inline float sky_mixture_density(const DirectionalQuadtree& guide, const glm::vec3& dir) {
    return sky_mixture_density(guide.pdf(dir));
}

// A unit direction toward the sky from the mixture, and its density. u.x picks the branch and is
// stretched back over [0, 1) inside it, so no sampler dimension is added.
inline glm::vec3 sample_sky_mixture(const DirectionalQuadtree& guide, glm::vec2 u, float& density) {
    constexpr float a = kSkyUniformFraction;
    if (u.x < a) {
        const glm::vec3 dir = uniform_sphere(std::min(u.x / a, kBelowOne), u.y);
        density = sky_mixture_density(guide, dir);
        return dir;
    }
    float d = 0.0f;
    const glm::vec3 dir = guide.sample(std::min((u.x - a) / (1.0f - a), kBelowOne), u.y, &d);
    density = sky_mixture_density(d);
    return dir;
}

}  // namespace sweeptrace

#pragma once
// Next event estimation guided by what it learned: where a light is blocked from most of a
// region of the scene (smallpt's light is a sphere of which only a small cap shows below the
// ceiling, so ~97% of its cone samples aim at the occluded part), the guide's spatial leaf also
// learns the distribution of NEE's own sample square (the two uniforms the light's cone maps to
// a point on it), from each sample's unweighted estimate radiance x cos / density. NEE then draws
// its square point from a defensive mixture: with probability kLightUniformFraction uniform,
// otherwise from the learned quadtree. The cone's map from the square is one to one, so the
// point's density is the cone's times the mixture's density on the square; LightSet::pdf maps a
// BSDF-found light point back to the square (cone_square in lights.cpp) and multiplies the same
// mixture density in, so MIS weighs both strategies with the densities they sampled with. The
// uniform part covers every point the unguided cone reaches, so nothing the unguided estimator
// sees is lost. Only cone-sampled lights (spheres seen from outside) read the guide; the others
// sample as before.
#include <algorithm>

#include <glm/vec2.hpp>

#include "raytracer/geometry/warps.hpp"
#include "raytracer/render/guiding/guiding_quadtree.hpp"

namespace sweeptrace {

inline constexpr float kLightUniformFraction = 0.25f;

// The mixture's density where the learned quadtree's density is `learned`.
inline float light_mixture_density(float learned) {
    return kLightUniformFraction + (1.0f - kLightUniformFraction) * learned;
}

// The mixture's density at point p of the square.
inline float light_square_density(const DirectionalQuadtree& guide, const glm::vec2& p) {
    return light_mixture_density(guide.pdf_square(p));
}

// The point of the square NEE uses in place of `u`, and the mixture's density there (area 1).
// u.x picks the branch and is stretched back over [0, 1) inside it, so no sampler dimension is
// added (the dimension layout, and so every unguided image, stays as it was).
inline glm::vec2 warp_light_sample(const DirectionalQuadtree& guide, glm::vec2 u, float& density) {
    constexpr float a = kLightUniformFraction;
    if (u.x < a) {
        u.x = std::min(u.x / a, kBelowOne);
        density = light_square_density(guide, u);
        return u;
    }
    float d = 0.0f;
    const glm::vec2 p = guide.sample_square(std::min((u.x - a) / (1.0f - a), kBelowOne), u.y, &d);
    density = light_mixture_density(d);
    return p;
}

}  // namespace sweeptrace

#pragma once
// The scene's background as a light at infinity, whatever its kind (scene/scene.hpp's
// Background): an environment map (render/lights/environment_light.hpp), a constant colour or the
// horizon-to-zenith sky. Next event estimation draws its directions, BSDF-sampled rays that
// escape find it (LightSet::escaped_radiance), and MIS weighs the two by the densities here.
//
// Next event estimation from a point p:
// - a map: its texel distribution (p plays no part);
// - a constant colour or the sky: uniform over the sphere, density 1 / (4 pi), as pbrt-v4's
//   UniformInfiniteLight; for the sky (radiance between the horizon's and the zenith's, at most
//   a few times apart) the proportional density would gain little;
// - with a portal (render/lights/portal.hpp), a colour or the sky: uniform in the portal's solid angle
//   from p, density 1 / Omega(p) through the portal and 0 elsewhere; a map: a one-sample mixture,
//   half its texel distribution and half the portal's, density the mean of the two. The mixture
//   keeps the map's bright texels (a sun) found at half the rate a portal-less map finds them,
//   where pbrt-v4's PortalImageInfiniteLight resamples the map into the portal's own
//   parameterisation and samples it windowed to the portal: better for a map with a sun in the
//   window, not done here.
// Emission (light subpaths, LightSet::sample_emission): a direction by the map's texel
// distribution or uniform over the sphere, whatever the portal (a portal bounds what a shading
// point sees, not where the sky's light enters a bounding disc), with emission_pdf() its density.
#include <optional>

#include <glm/vec3.hpp>

#include "raytracer/render/lights/environment_light.hpp"
#include "raytracer/render/lights/portal.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// Radiance of the background along unit direction `dir`, whatever its kind. Sky: the horizon's
// below the horizon, blended linearly in dir.y up to the zenith's.
glm::vec3 background_radiance(const Background& bg, const glm::vec3& dir);

class BackgroundLight {
public:
    explicit BackgroundLight(const Background& bg);

    bool emits() const { return max_irradiance_ > 0.0; }
    // The largest irradiance (luminance) the background gives a small disc over the disc's
    // orientations, light selection's weight for lights at infinity (lights.hpp): the map's
    // (EnvironmentLight::max_irradiance), pi lum(L) for a colour, and for the sky
    // pi max(lum(horizon), lum(zenith)), an upper bound (facing up it gets pi (h + 2 z) / 3).
    double max_irradiance() const { return max_irradiance_; }

    glm::vec3 radiance(const glm::vec3& dir) const { return background_radiance(*bg_, dir); }
    // Next event estimation from p: a unit direction toward the background from two uniforms in
    // [0, 1), its solid-angle density and the radiance along it; false for a sample of density 0.
    bool sample(const glm::vec3& p, float u1, float u2, glm::vec3& dir, float& pdf, glm::vec3& radiance) const;
    // The density sample(p, ...) gives unit direction `dir`.
    float pdf(const glm::vec3& p, const glm::vec3& dir) const;

    // Emission's direction toward the background (the portal plays no part), and its density.
    bool sample_emission(float u1, float u2, glm::vec3& dir, float& pdf, glm::vec3& radiance) const;
    float emission_pdf(const glm::vec3& dir) const;

private:
    const Background* bg_;
    std::optional<EnvironmentLight> env_;  // a map
    std::optional<Portal> portal_;
    double max_irradiance_ = 0.0;
};

}  // namespace sweeptrace

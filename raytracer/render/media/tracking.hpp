#pragma once
// Collisions along a ray through one medium (medium_model.hpp), the two estimators every
// integrator uses:
//   - delta tracking (free-flight sampling): tentative collisions at the majorant's rate mu; at
//     each, the medium absorbs, scatters or lets the path pass (a null collision) with
//     probabilities sigma_a / mu, sigma_s / mu and 1 - sigma_t / mu. With mu = sigma_t (a grey
//     homogeneous medium) there are no null collisions and this is exact exponential sampling.
//   - ratio tracking (transmittance): the same tentative collisions, each multiplying the
//     estimate by 1 - sigma_t / mu per channel; unbiased, with no fixed step and no bias from a
//     step size (Novak et al. 2014). Homogeneous media have it in closed form, exp(-sigma_t d).
//
// Chromatic media (sigma differing per channel) take spectral MIS (pbrt-v4's volpath, Tungsten):
// each camera path picks a hero channel h uniformly, its event probabilities come from channel
// h, and the path carries the ratios r_u[c] = p_c / p_h of the densities the other channels
// would have sampled it with. A contribution is (f / p_h) L / mean(r_u): the one-sample balance
// heuristic over the three channels' strategies, so a channel the hero barely samples is covered
// by its own strategy instead of by huge weights. The path's throughput `beta` holds
// (f / p_h) / mean(r_u) itself, so the integrators use it as in vacuum; r_u is kept at mean 1
// (only its ratios matter). For grey media every ratio is 1 and nothing changes. Absorption ends
// the path (it carries no light further).
#include <cmath>

#include <glm/vec3.hpp>

#include "raytracer/render/media/medium_model.hpp"
#include "raytracer/render/sampling/random.hpp"

namespace sweeptrace {

inline float mean_of_channels(const glm::vec3& v) { return (v.x + v.y + v.z) / 3.0f; }

enum class Flight { Passed, Scattered, Absorbed };

struct FlightResult {
    Flight event = Flight::Passed;
    float t = 0.0f;              // where it scattered
    glm::vec3 emitted{0.0f};     // the medium's emission collected on the way, times beta
    std::uint64_t collisions = 0;  // tentative collisions (null ones included), for the benchmark
};

// Delta tracking along o + t d (unit d) over [tmin, tmax) (tmax: the next surface, or infinity),
// updating the path's beta and r_u (mean 1) with the hero channel `hero` (0, 1, 2). `emission`: collect
// the medium's emitted radiance (a collision estimator of the integral of T sigma_a Le, added at
// every tentative collision before its event is chosen, as pbrt-v4 does).
FlightResult delta_track(const MediumModel& m, const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, int hero,
                         Rng& rng, glm::vec3& beta, glm::vec3& r_u, bool emission);

// Ratio-tracking transmittance of each channel along o + t d (unit d) over [tmin, tmax] (finite
// for grids; a homogeneous medium may give infinity). Unbiased; its expectation is
// exp(-integral of sigma_t). `collisions` (if given) counts the tentative collisions.
glm::vec3 ratio_track(const MediumModel& m, const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, Rng& rng,
                      std::uint64_t* collisions = nullptr);

// The transmittance the integrators use: exact for homogeneous media, ratio tracking for grids.
glm::vec3 transmittance(const MediumModel& m, const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, Rng& rng);

}  // namespace sweeptrace

#pragma once
// Russian roulette: when a path may stop, and with what probability it goes on.
//
// The policy, stated once: from path vertex `start_depth` on (depth as the integrator counts it,
// 1 = the first hit), a path whose throughput t (the largest RGB component of its weight relative
// to the camera ray's, with the 1/eta^2 radiance scaling of refractions undone when
// `undo_refraction_scale`, so a path inside glass is not punished for a factor it gives back on
// the way out) has fallen below `threshold` survives with probability t / threshold and its
// weight is divided by that, so a survivor's throughput is `threshold` again. Above the
// threshold a path is never stopped: killing high-weight paths adds variance without saving
// much time. The estimator is unbiased for any policy (E[weight / q * (survive)] = weight).
//
// classic() is the renderer's roulette before #15 (from the third vertex, q = min(1, max(beta))).
// adaptive() is the default: from the second vertex, below throughput 1, refractions undone. Of
// the candidates `sweeptrace accuracy --sampling` measures (docs/sampling.md), it had the lowest
// per-sample variance x CPU time relative to classic(), averaged over the five shipped scenes
// (0.92; from vertex 3 with eta undone 0.93, within timing noise; thresholds 0.1-0.5 cut the
// per-sample variance of the glass scenes but lengthen paths by more: 0.96-1.11).
#include <glm/vec3.hpp>

#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

struct RoulettePolicy {
    int start_depth = 3;
    float threshold = 1.0f;
    bool undo_refraction_scale = false;

    static constexpr RoulettePolicy classic() { return {3, 1.0f, false}; }
    static constexpr RoulettePolicy adaptive() { return {2, 1.0f, true}; }
};

// Probability that a path with throughput t at vertex `depth` goes on (1: no roulette here).
inline float survival_probability(const RoulettePolicy& p, int depth, float t) {
    if (depth < p.start_depth || !(t < p.threshold)) return 1.0f;
    return t / p.threshold;
}

// The roulette at vertex `depth` with uniform u: false when the path stops; otherwise `beta` is
// divided by the survival probability. eta_scale: the product of eta^2 over the path's refractions.
// guide_scale (>= 1): with path guiding, the ratio by which guided vertices' mixture densities
// lowered the throughput below what BSDF sampling would have given; the path is judged by the
// latter, so roulette does not end the guided paths that head for a light (any continuation
// probability in (0, 1] stays unbiased).
inline bool survives_roulette(const RoulettePolicy& p, int depth, float u, float eta_scale, glm::vec3& beta,
                              float guide_scale = 1.0f) {
    const float t = max_component(p.undo_refraction_scale ? beta * eta_scale : beta) * guide_scale;
    const float q = survival_probability(p, depth, t);
    if (!(u < q)) return false;
    beta /= q;
    return true;
}

}  // namespace sweeptrace

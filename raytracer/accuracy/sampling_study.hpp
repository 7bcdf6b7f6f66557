#pragma once
// The sampler and roulette study behind `sweeptrace accuracy --sampling SCENE...` (issue #15).
// A benchmark: it prints what it measured and asserts nothing.
//
// Per scene, at `size` pixels wide (the scene's aspect and max_depth kept), one thread:
// - a converged reference: independent sampler, the default roulette, reference_spp samples on
//   all cores, cached as EXR (image + variance) under `cache_dir`, keyed by the scene file's
//   contents, size, depth and spp;
// - today's estimator (independent + classic roulette) against sobol / adaptive roulette and
//   their mixes at 16, 64, 256, 1024 spp: RMSE over the interior pixels (more than 3 px from
//   every edge) against the reference, with the reference's own noise removed (its per-pixel
//   variance of the mean subtracted from the mean squared error: E[(x - r)^2] = E[(x - mu)^2] +
//   Var r for independent renders), CPU seconds, and the equal-time RMSE ratio against today:
//   (RMSE / RMSE_today) * sqrt(t / t_today), i.e. today's error extrapolated to the same CPU
//   time by its 1/sqrt(t) law (independent samples: exactly that law);
// - the fitted slope of log RMSE against log spp over the four spp;
// - roulette candidates: per-sample variance (mean over interior pixels and channels of the
//   independent sampler's sample variance), CPU microseconds per sample, and their product at
//   roulette_spp, per policy, and that product relative to classic().
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "raytracer/render/sampling/roulette.hpp"

namespace sweeptrace::accuracy {

struct SamplingRow {
    std::string scene, sampler, roulette;  // sampler: sobol | independent; roulette: classic | adaptive
    int spp = 0;
    double seconds = 0.0;       // CPU seconds of the render (1 thread)
    double rmse = 0.0;          // interior pixels, reference noise removed
    double equal_time = 0.0;    // RMSE ratio against independent + classic at equal CPU time
    double slope = 0.0;         // fitted over the four spp (same on every row of a configuration)
};

struct RouletteRow {
    std::string scene;
    RoulettePolicy policy;
    double per_sample_variance = 0.0;
    double us_per_sample = 0.0;
    double product = 0.0;       // variance x time
    double relative = 0.0;      // product / classic()'s
};

struct SamplingReport {
    int width = 0;  // of the first scene (each keeps its aspect)
    int reference_spp = 0, roulette_spp = 0;
    std::vector<SamplingRow> rows;
    std::vector<RouletteRow> roulette;
};

// convergence = false: the roulette candidates only (no reference, no convergence rows).
SamplingReport sampling_study(const std::vector<std::filesystem::path>& scenes, int size, int reference_spp,
                              int roulette_spp, const std::filesystem::path& cache_dir, bool convergence = true);

void write_sampling_markdown(std::ostream& out, const SamplingReport& report);
void write_sampling_csv(std::ostream& out, const SamplingReport& report);

}  // namespace sweeptrace::accuracy

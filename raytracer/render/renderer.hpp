#pragma once
// Rendering a scene through an acceleration structure into a linear-RGB image.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "raytracer/accel/accel.hpp"
#include "raytracer/render/adaptive_sampling.hpp"
#include "raytracer/image/feature_sums.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/render/sampling/roulette.hpp"
#include "raytracer/image/partial_sum.hpp"
#include "raytracer/render/time_budget.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

class PathForensics;

// With AOVs, how many finished passes' colours and features the renderer holds per pixel before
// adding them to the exact feature sums at once (the memory estimate counts them).
inline constexpr std::size_t kAovPendingPasses = 4;

enum class Sampling {
    NeeMis,    // next event estimation + BSDF sampling, combined by the power heuristic
    BsdfOnly,  // light found only by BSDF-sampled paths (the reference the MIS test compares to)
    // Bidirectional only: light found only by light subpaths joined to the lens (t = 1, each at
    // full weight), an estimator independent of the camera's; the light-tracing test's.
    LightTracing,
};

// What the progress callback sees.
struct RenderProgress {
    double fraction = 0.0;    // of the spp target or of the time budget, whichever is further
    int completed_spp = 0;    // passes finished
    double seconds = 0.0;     // elapsed on the budget's clock
    double seconds_left = -1.0;  // of the time budget; negative without one
};

struct RenderOptions {
    int spp = 16;  // with a time budget: the most passes to render
    // Renders sample indices [first_sample, first_sample + spp) of every pixel: the same samples,
    // from the same random streams, that a render from 0 draws for those indices (a farm part).
    int first_sample = 0;
    int max_depth = 8;
    int threads = 0;  // 0 = all cores
    std::uint64_t seed = 0;
    Sampling sampling = Sampling::NeeMis;
    SamplerKind sampler = SamplerKind::Sobol;  // callers copy scene.film.sampler here
    IntegratorKind integrator = IntegratorKind::Path;  // callers copy scene.film.integrator here
    RoulettePolicy roulette = RoulettePolicy::adaptive();
    // Path guiding (render/guiding_*.hpp): learned from whole passes, so the image stays the same
    // for any thread count; unbiased, like the unguided render of the same scene.
    bool guiding = false;
    // Noise forensics (path_forensics.hpp): when set, every sample's contributions are recorded
    // there by path type, per 16x16 tile; the image is the same bit for bit.
    PathForensics* forensics = nullptr;
    // Adaptive sampling (adaptive_sampling.hpp): a uniform pilot of kAdaptivePilotSpp passes, then
    // per-pixel counts from the pilot's error, more to noisier 8x8 tiles: pixel p gets samples
    // 0..n_p-1 of its own sequence, n_p = 16 + adaptive_count(w_p, spp - 16), the mean of n_p
    // within 1/2 of spp. Path integrator only, without guiding or forensics. first_sample and spp
    // then name the nominal range [first_sample, first_sample + spp) of a farm part: the pilot's
    // passes in it, and past the pilot each pixel's samples between its counts at either end (the
    // part renders the whole pilot for its weights). spp <= the pilot: the uniform render exactly.
    bool adaptive = false;
    AdaptiveError adaptive_error = AdaptiveError::Mse;  // where the samples after the pilot go (adaptive_sampling.hpp)
    // Feature outputs (render --aovs): every sample's albedo, normal and position at its first
    // non-specular camera vertex (sample_features.hpp) summed per pixel and half (RenderResult::
    // features); the image is the same bit for bit.
    bool aovs = false;
    const std::atomic<bool>* cancel = nullptr;  // set (e.g. by SIGINT) to stop early
    // Seconds (0 = none) after which the pass in flight is dropped and the render ends; the first
    // pass always completes. Counted on budget_clock from the start of render().
    double time_budget = 0.0;
    BudgetClock budget_clock = BudgetClock::Wall;
    // Called now and then from one thread.
    std::function<void(const RenderProgress&)> progress;
};

struct RenderStats {
    double seconds = 0.0;
    std::uint64_t samples = 0;  // camera samples completed
    std::uint64_t rays = 0;     // every ray traced (camera, bounce, shadow)
    bool cancelled = false;      // stopped by `cancel`
    bool budget_spent = false;   // stopped by the time budget before reaching spp
    // Samples per pixel in the returned image. Adaptive: the nominal spp reached from first_sample
    // (the image is a render with that spp's; pixel_samples has each pixel's own count).
    int completed_spp = 0;
    // Samples whose radiance came out NaN or infinite, counted and replaced by black so one bad
    // path cannot poison a pixel; non-zero means a bug worth reporting.
    std::uint64_t nonfinite_samples = 0;
    // Sample channels beyond +-kSampleLimit (partial_sum.hpp), clamped to it; non-zero means a bug.
    std::uint64_t clamped_samples = 0;
};

struct RenderResult {
    Image image;  // mean radiance per pixel of the completed samples: mean_of(sums[i], completed_spp)
    // Exact fixed-point sum per pixel of the completed samples (partial_sum.hpp): what a farm part
    // stores, and what makes a merged farm render equal to this image bit for bit.
    std::vector<PixelSum> sums;
    // Estimated variance of each pixel's mean, per channel: the unbiased sample variance of the
    // pixel's samples divided by its sample count (zero below 2 samples). For tests whose
    // tolerances come from the noise (z-tests on pixel or block means).
    Image variance;
    // Adaptive only: each pixel's sample count n_p (its mean is sums[i] / n_p, its variance is
    // from its own n_p samples). Empty for a uniform render (every pixel has completed_spp).
    std::vector<int> pixel_samples;
    // With RenderOptions::aovs: per pixel, the colour and features of its samples in exact sums,
    // even and odd samples apart (image/feature_sums.hpp); a farm part stores them. Empty without.
    std::vector<FeatureSums> features;
    RenderStats stats;
};

// Same scene + options (seed, spp, max_depth, sampling, sampler, roulette) give the same image bit for bit whatever
// `threads` is: every pixel sample's numbers are addressed by (seed, pixel, sample, dimension).
// The image size is scene.film's; spp and max_depth are the options'. Rendering runs in passes of
// one sample per pixel; when `cancel` is set, the pass in flight is dropped, so every pixel of
// the returned image holds the same completed_spp samples (0: a black image), and the image is
// bit for bit the one a render with spp = completed_spp gives.
// A time budget ends the render the same way (after at least one pass): the image is the one
// spp = completed_spp gives.
// Throws std::invalid_argument for a film smaller than 1x1, spp < 1, max_depth < 1, threads < 0,
// Sampling::LightTracing with the path integrator, any sampling but NeeMis with vcm, guiding with bdpt or vcm,
// first_sample < 0 or first_sample + spp beyond INT_MAX, time_budget < 0, adaptive with bdpt, vcm,
// guiding or forensics.
RenderResult render(const Scene& scene, const Accel& accel, const RenderOptions& options);

}  // namespace sweeptrace

#pragma once
// Rendering a scene through an acceleration structure into a linear-RGB image.
#include <atomic>
#include <cstdint>
#include <functional>

#include "raytracer/accel/accel.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/render/time_budget.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

enum class Sampling {
    NeeMis,    // next event estimation + BSDF sampling, combined by the power heuristic
    BsdfOnly,  // light found only by BSDF-sampled paths (the reference the MIS test compares to)
};

// Defects planted on purpose, for the golden-image mutation tests only: they show that the image
// tests reject a renderer with this bug. Never set by the command line.
enum class PlantedDefect { None, FlippedNormals, NoRayOffset };

// What the progress callback sees.
struct RenderProgress {
    double fraction = 0.0;    // of the spp target or of the time budget, whichever is further
    int completed_spp = 0;    // passes finished
    double seconds = 0.0;     // elapsed on the budget's clock
    double seconds_left = -1.0;  // of the time budget; negative without one
};

struct RenderOptions {
    int spp = 16;  // with a time budget: the most passes to render
    int max_depth = 8;
    int threads = 0;  // 0 = all cores
    std::uint64_t seed = 0;
    Sampling sampling = Sampling::NeeMis;
    // Path guiding (render/guiding_*.hpp): learned from whole passes, so the image stays the same
    // for any thread count; unbiased, like the unguided render of the same scene.
    bool guiding = false;
    PlantedDefect defect = PlantedDefect::None;
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
    int completed_spp = 0;      // samples per pixel in the returned image
    // Samples whose radiance came out NaN or infinite, counted and replaced by black so one bad
    // path cannot poison a pixel; non-zero means a bug worth reporting.
    std::uint64_t nonfinite_samples = 0;
};

struct RenderResult {
    Image image;  // mean radiance per pixel of the completed samples
    // Estimated variance of each pixel's mean, per channel: the unbiased sample variance of the
    // pixel's samples divided by completed_spp (zero when completed_spp < 2). For tests whose
    // tolerances come from the noise (z-tests on pixel or block means).
    Image variance;
    RenderStats stats;
};

// Same scene + options (seed, spp, max_depth, sampling) give the same image bit for bit whatever
// `threads` is: every pixel sample draws from its own random stream.
// The image size is scene.film's; spp and max_depth are the options'. Rendering runs in passes of
// one sample per pixel; when `cancel` is set, the pass in flight is dropped, so every pixel of
// the returned image holds the same completed_spp samples (0: a black image), and the image is
// bit for bit the one a render with spp = completed_spp gives.
// A time budget ends the render the same way (after at least one pass): the image is the one
// spp = completed_spp gives.
// Throws std::invalid_argument for a film smaller than 1x1, spp < 1, max_depth < 1, threads < 0,
// time_budget < 0.
RenderResult render(const Scene& scene, const Accel& accel, const RenderOptions& options);

}  // namespace sweeptrace

#pragma once
// Adaptive sampling (issue 34 item 2, after Tungsten's renderer): a uniform pilot, then per-pixel
// sample counts from the pilot's estimated error, more to the noisier 8x8 tiles. The allocation is
// a pure function of the pilot, computed once on one thread in a fixed order, so every farm part
// recomputes it from the same 16 passes and knows its own samples without the rest of the image
// (renderer.cpp, docs/equal-time-interiors.md): the image is the same for any thread count and any
// split into parts; only how many passes fit in a --time budget depends on the clock.
//
// The schedule: after the pilot, a render of "nominal" spp N gives pixel p
// adaptive_count(w_p, N - 16) more samples, its indices 16, 17, ... of its own sequence, where w_p
// is its tile's weight (mean 1 over the image). Since the count only grows with the budget, the
// samples of the nominal range [A, B) are, per pixel, those between the counts at A and at B: a
// farm part's whole definition.
//
// Why each constant:
// - kAdaptiveTile 8: an 8x8 tile after the pilot holds 64 x 16 samples, enough that one firefly
//   moves its estimate rather than dominating it (Tungsten uses 4x4; 4x4 was not measured here).
// - kAdaptivePilotSpp 16: Tungsten's; below it a tile's variance is mostly noise itself.
// - kAdaptiveRoundSpp 8: the nominal spp of one pass after the pilot: small passes waste little of
//   a --time budget (the pass in flight when it runs out is dropped whole, see renderer.cpp).
// - kAdaptiveCapPercentile 0.95: a tile's error counts at most as the 95th percentile's, so a
//   few tiles with fireflies cannot take the samples (Tungsten's threshold).
// - kAdaptiveUniformShare 1/8: that share of the samples after the pilot goes to all pixels alike,
//   so a tile whose pilot saw nothing (a dark corner lit by a rare path) still converges, and the
//   allocation's dependence on the samples (the source of adaptive sampling's small bias) stays
//   bounded.
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/image/partial_sum.hpp"

namespace sweeptrace {

// What a tile's error is, and so where samples go (both measured on the pilot, where every pixel
// has the same count):
// - Relative (Tungsten's): the relative variance of the tile's mean; samples in proportion to
//   it. Equalises the error relative to brightness, what a tone-mapped picture shows, and so
//   favours dark tiles.
// - Mse: minimum mean squared error of the linear image. For a fixed total, sum_p sigma_p^2 / n_p
//   is least with n_p in proportion to sigma_p (each pixel's per-sample standard deviation), so
//   samples go in proportion to the tile's sigma.
enum class AdaptiveError { Relative, Mse };

inline constexpr int kAdaptiveTile = 8;
inline constexpr int kAdaptivePilotSpp = 16;
inline constexpr int kAdaptiveRoundSpp = 8;
inline constexpr double kAdaptiveCapPercentile = 0.95;
inline constexpr double kAdaptiveUniformShare = 0.125;

// The 8x8 tiles of a width x height image, row by row (the last row and column may be smaller).
struct AdaptiveTiles {
    int width = 0, height = 0, tiles_x = 0, tiles_y = 0;
    AdaptiveTiles(int w, int h);
    int count() const { return tiles_x * tiles_y; }
    int of_pixel(int x, int y) const { return (y / kAdaptiveTile) * tiles_x + x / kAdaptiveTile; }
    int pixels_in(int tile) const;
};

// Each tile's weight from its error: kAdaptiveUniformShare + (1 - kAdaptiveUniformShare) x the
// error capped at the kAdaptiveCapPercentile-th percentile / the image's mean capped error, so
// the pixel-weighted mean weight is 1. All-zero errors give every tile weight 1 (uniform).
std::vector<double> adaptive_tile_weights(const AdaptiveTiles& tiles, const std::vector<double>& errors);

// The weight of every pixel, row-major: what the schedule reads, from the pilot's per-pixel sums
// alone (every pixel holding `pilot_spp` samples), by `error`'s rule (adaptive_sampling.cpp,
// tile_errors, states the two errors; each tile's error is the mean over its 3x3 tiles, a steadier
// estimate where the noise is fireflies). Cross-fitted on a checkerboard: the pixels with x + y even
// get their tile's weight from the odd pixels alone (each tile's error, the percentile cap, the
// mean, the relative rule's floor), and the odd ones from the even ones. So a pixel's count never
// depends on its own samples, and its mean over them is exactly unbiased (a pixel's samples are
// independent of every other pixel's: their own random streams). A tile with no pixel of the
// other colour (a 1x1 corner tile) has error 0: the uniform share.
std::vector<double> adaptive_pixel_weights(const AdaptiveTiles& tiles, AdaptiveError error, const std::vector<PixelSum>& sums,
                                           const std::vector<glm::dvec3>& sum_sq, int pilot_spp);

// Samples after the pilot of a pixel of weight w at a nominal budget of `t` spp beyond it:
// round(t x w), never fewer at a larger t. Over the image the mean is t to within 1/2 (the
// weights' mean is 1), so a render of nominal spp N holds N samples per pixel on average, +-1/2.
inline std::int64_t adaptive_count(double weight, std::int64_t t) {
    return static_cast<std::int64_t>(std::floor(static_cast<double>(t) * weight + 0.5));
}

}  // namespace sweeptrace

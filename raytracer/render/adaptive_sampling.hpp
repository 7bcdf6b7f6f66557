#pragma once
// Adaptive sampling (issue 34 item 2, after Tungsten's renderer): a uniform pilot, then rounds
// that each hand out a fixed number of samples, more to the 8x8 tiles whose mean is estimated
// to be further from the truth. Everything here is a pure function of the image so far, computed
// on one thread in a fixed order, so the allocation (and so the image) is the same for any
// thread count; only how many rounds fit in a --time budget depends on the clock.
//
// Why each constant:
// - kAdaptiveTile 8: an 8x8 tile after the pilot holds 64 x 16 samples, enough that one firefly
//   moves its estimate rather than dominating it (Tungsten uses 4x4; 4x4 was not measured here).
// - kAdaptivePilotSpp 16: Tungsten's; below it a tile's variance is mostly noise itself.
// - kAdaptiveRoundSpp 8: small rounds re-estimate often and waste little of a --time budget
//   (the round in flight when it runs out is dropped whole, see renderer.cpp).
// - kAdaptiveCapPercentile 0.95: a tile's error counts at most as the 95th percentile's, so a
//   few tiles with fireflies cannot take the whole round (Tungsten's threshold).
// - kAdaptiveUniformShare 1/8: that share of every round goes to all pixels alike, so a tile
//   whose pilot saw nothing (a dark corner lit by a rare path) still converges, and the
//   allocation's dependence on the samples (the source of adaptive sampling's small bias) stays
//   bounded.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/image/partial_sum.hpp"

namespace sweeptrace {

// What a tile's error is, and so where samples go:
// - Relative (Tungsten's): the relative variance of the tile's mean; each round in proportion to
//   it. Equalises the error relative to brightness, what a tone-mapped picture shows, and so
//   favours dark tiles.
// - Mse: minimum mean squared error of the linear image. For a fixed total, sum_p sigma_p^2 / n_p
//   is least with n_p in proportion to sigma_p (each pixel's per-sample standard deviation), so
//   each round fills the tiles whose counts are furthest below that share of all the samples
//   spent so far and in this round.
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

// Per tile, the relative variance of its mean radiance: the mean over its pixels of each pixel
// mean's estimated variance (the unbiased sample variance from the pixel's own count, / count,
// averaged over channels), divided by the square of the tile's mean radiance plus a floor of
// (1% of the image's mean)^2, so a black tile's variance is not divided by zero. Pixels with
// fewer than 2 samples count as variance 0. `counts` is samples per pixel.
std::vector<double> adaptive_tile_errors(const AdaptiveTiles& tiles, const std::vector<PixelSum>& sums,
                                         const std::vector<glm::dvec3>& sum_sq, const std::vector<int>& counts);

// Per tile, the per-sample standard deviation: the square root of the mean over its pixels of the
// unbiased sample variance (averaged over channels). Pixels with fewer than 2 samples count as 0.
std::vector<double> adaptive_tile_deviations(const AdaptiveTiles& tiles, const std::vector<PixelSum>& sums,
                                             const std::vector<glm::dvec3>& sum_sq, const std::vector<int>& counts);

// Samples per pixel for the next round, `budget` in all (exactly, when budget >= 0): a share
// kAdaptiveUniformShare spread evenly, the rest in proportion to each tile's error capped at the
// kAdaptiveCapPercentile-th percentile. Pixels of one tile get the same count, except that the
// rounding's leftover samples go one per pixel to the tiles with the largest fractional parts
// (in tile then pixel order), so the total is exact. All-zero errors give a uniform round.
std::vector<int> adaptive_round(const AdaptiveTiles& tiles, const std::vector<double>& errors, std::int64_t budget);

// AdaptiveError::Mse's round: the uniform share as above; the rest in proportion to each tile's
// shortfall below its share of all samples after the round, sigma_t (capped at the percentile) /
// the image's mean sigma x (samples so far + budget) / pixels, per pixel, against the tile's
// mean count so far. `counts` is samples per pixel so far. Same exact total and rounding as
// adaptive_round.
std::vector<int> adaptive_round_mse(const AdaptiveTiles& tiles, const std::vector<double>& deviations,
                                    const std::vector<int>& counts, std::int64_t budget);

}  // namespace sweeptrace

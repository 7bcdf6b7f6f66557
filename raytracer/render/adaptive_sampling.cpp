#include "raytracer/render/adaptive_sampling.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace sweeptrace {

AdaptiveTiles::AdaptiveTiles(int w, int h)
    : width(w), height(h), tiles_x((w + kAdaptiveTile - 1) / kAdaptiveTile), tiles_y((h + kAdaptiveTile - 1) / kAdaptiveTile) {}

int AdaptiveTiles::pixels_in(int tile) const {
    const int x0 = (tile % tiles_x) * kAdaptiveTile, y0 = (tile / tiles_x) * kAdaptiveTile;
    return (std::min(x0 + kAdaptiveTile, width) - x0) * (std::min(y0 + kAdaptiveTile, height) - y0);
}

namespace {

// A pixel's mean radiance and the unbiased variance of its samples (0 below 2), each averaged
// over the channels: the one place both tile measures read a pixel.
struct PixelMoments {
    double mean = 0.0, sample_variance = 0.0;
};
PixelMoments pixel_moments(const PixelSum& sum, const glm::dvec3& sum_sq, int count) {
    PixelMoments pm;
    if (count < 1) return pm;
    const glm::dvec3 m = sum_value(sum) / double(count);
    pm.mean = (m.x + m.y + m.z) / 3.0;
    if (count > 1) {
        const glm::dvec3 s2 = glm::max(sum_sq - double(count) * m * m, glm::dvec3(0.0)) / double(count - 1);
        pm.sample_variance = (s2.x + s2.y + s2.z) / 3.0;
    }
    return pm;
}

// The pixels a tile measure reads: all of them, or one colour of the checkerboard ((x + y) % 2).
constexpr int kAllPixels = -1;
bool in_set(int x, int y, int parity) { return parity == kAllPixels || ((x + y) & 1) == parity; }

// Per tile, the number of its pixels in the set.
std::vector<double> pixels_per_tile(const AdaptiveTiles& tiles, int parity) {
    std::vector<double> n(static_cast<std::size_t>(tiles.count()), 0.0);
    for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x)
            if (in_set(x, y, parity)) n[static_cast<std::size_t>(tiles.of_pixel(x, y))] += 1.0;
    return n;
}

// Each tile's value replaced by the mean over its 3x3 neighbourhood of tiles (those inside the
// image). Why: where the noise is fireflies, 16 pilot samples of one tile's 32 pixels of a colour
// mostly say which tiles happened to catch one, and following that moves samples at random; nine
// tiles' pixels estimate the noise of the region (classroom, docs/equal-time-interiors.md: 0.88 of
// the unsmoothed RMSE at equal time, 0.97 to 1.02 on the other five scenes).
std::vector<double> neighbourhood_mean(const AdaptiveTiles& tiles, const std::vector<double>& v) {
    std::vector<double> out(v.size(), 0.0);
    for (int ty = 0; ty < tiles.tiles_y; ++ty)
        for (int tx = 0; tx < tiles.tiles_x; ++tx) {
            double sum = 0.0, count = 0.0;
            for (int y = std::max(ty - 1, 0); y <= std::min(ty + 1, tiles.tiles_y - 1); ++y)
                for (int x = std::max(tx - 1, 0); x <= std::min(tx + 1, tiles.tiles_x - 1); ++x) {
                    sum += v[static_cast<std::size_t>(y) * tiles.tiles_x + x];
                    count += 1.0;
                }
            out[static_cast<std::size_t>(ty) * tiles.tiles_x + tx] = sum / count;
        }
    return out;
}

// Per tile, the error of AdaptiveError's rule, read from the tile's pixels in the set alone (a
// tile with none of them: 0), then averaged over its neighbourhood (neighbourhood_mean). Every
// pixel holds `count` samples (the pilot's).
// - Relative: the relative variance of the tile's mean radiance, the mean over its pixels of each
//   pixel mean's estimated variance (the unbiased sample variance / count, averaged over
//   channels) divided by the square of the tile's mean radiance plus a floor of (1% of the set's
//   mean)^2, so a black tile's variance is not divided by zero.
// - Mse: the per-sample standard deviation, the square root of the mean over its pixels of the
//   unbiased sample variance (averaged over channels).
std::vector<double> tile_errors(const AdaptiveTiles& tiles, AdaptiveError rule, const std::vector<PixelSum>& sums,
                                const std::vector<glm::dvec3>& sum_sq, int count, int parity) {
    const auto n = static_cast<std::size_t>(tiles.count());
    std::vector<double> var(n, 0.0), mean(n, 0.0);
    const std::vector<double> k = pixels_per_tile(tiles, parity);
    double set_mean = 0.0, set_pixels = 0.0;
    for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x) {
            if (!in_set(x, y, parity)) continue;
            const std::size_t p = static_cast<std::size_t>(y) * tiles.width + x;
            const PixelMoments pm = pixel_moments(sums[p], sum_sq[p], count);
            const auto t = static_cast<std::size_t>(tiles.of_pixel(x, y));
            var[t] += pm.sample_variance;
            mean[t] += pm.mean;
            set_mean += pm.mean;
            set_pixels += 1.0;
        }
    set_mean /= std::max(set_pixels, 1.0);
    const double floor = 1e-4 * set_mean * set_mean + 1e-30;
    std::vector<double> err(n, 0.0);
    for (std::size_t t = 0; t < n; ++t) {
        if (k[t] == 0.0) continue;
        const double m = mean[t] / k[t];
        err[t] = rule == AdaptiveError::Relative ? (var[t] / k[t] / double(count)) / (m * m + floor) : std::sqrt(var[t] / k[t]);
    }
    return neighbourhood_mean(tiles, err);
}

// The errors capped at the kAdaptiveCapPercentile-th percentile, by nth_element on a copy (a
// deterministic order statistic; ties do not matter, the value is the same). All ones when the
// cap is zero (no tile has an error yet).
std::vector<double> capped(const std::vector<double>& errors) {
    std::vector<double> sorted(errors);
    const auto k = static_cast<std::size_t>(kAdaptiveCapPercentile * double(errors.size() - 1));
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
    const double cap = sorted[k];
    std::vector<double> w(errors.size(), 1.0);
    if (cap > 0.0 && std::isfinite(cap))
        for (std::size_t t = 0; t < errors.size(); ++t) w[t] = std::min(errors[t], cap);
    return w;
}

// adaptive_tile_weights for tiles whose weights serve `pixels[t]` pixels each: the mean is 1 over
// those pixels.
std::vector<double> weights_of(const std::vector<double>& errors, const std::vector<double>& pixels) {
    const std::vector<double> e = capped(errors);
    double sum = 0.0, total = 0.0;
    for (std::size_t t = 0; t < e.size(); ++t) {
        sum += e[t] * pixels[t];
        total += pixels[t];
    }
    const double mean_e = sum / std::max(total, 1.0);
    std::vector<double> w(e.size(), 1.0);
    if (mean_e > 0.0 && std::isfinite(mean_e))
        for (std::size_t t = 0; t < e.size(); ++t) w[t] = kAdaptiveUniformShare + (1.0 - kAdaptiveUniformShare) * e[t] / mean_e;
    return w;
}

}  // namespace

std::vector<double> adaptive_tile_weights(const AdaptiveTiles& tiles, const std::vector<double>& errors) {
    return weights_of(errors, pixels_per_tile(tiles, kAllPixels));
}

std::vector<double> adaptive_pixel_weights(const AdaptiveTiles& tiles, AdaptiveError error, const std::vector<PixelSum>& sums,
                                           const std::vector<glm::dvec3>& sum_sq, int pilot_spp) {
    // weights[q]: per tile, for the pixels of colour q, from the pixels of the other colour alone.
    std::vector<double> weights[2];
    for (int q = 0; q < 2; ++q)
        weights[q] = weights_of(tile_errors(tiles, error, sums, sum_sq, pilot_spp, 1 - q), pixels_per_tile(tiles, q));
    std::vector<double> w(sums.size());
    for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x)
            w[static_cast<std::size_t>(y) * tiles.width + x] = weights[(x + y) & 1][static_cast<std::size_t>(tiles.of_pixel(x, y))];
    return w;
}

}  // namespace sweeptrace

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

}  // namespace

std::vector<double> adaptive_tile_errors(const AdaptiveTiles& tiles, const std::vector<PixelSum>& sums,
                                         const std::vector<glm::dvec3>& sum_sq, const std::vector<int>& counts) {
    const int n = tiles.count();
    std::vector<double> var(static_cast<std::size_t>(n), 0.0), mean(static_cast<std::size_t>(n), 0.0);
    double image_mean = 0.0;
    for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * tiles.width + x;
            const int c = counts[p];
            if (c < 1) continue;
            const PixelMoments pm = pixel_moments(sums[p], sum_sq[p], c);
            const auto t = static_cast<std::size_t>(tiles.of_pixel(x, y));
            var[t] += pm.sample_variance / double(c);  // the variance of the pixel's mean
            mean[t] += pm.mean;
            image_mean += pm.mean;
        }
    image_mean /= double(tiles.width) * double(tiles.height);
    const double floor = 1e-4 * image_mean * image_mean + 1e-30;
    std::vector<double> err(static_cast<std::size_t>(n));
    for (int t = 0; t < n; ++t) {
        const double k = tiles.pixels_in(t);
        const double m = mean[static_cast<std::size_t>(t)] / k;
        err[static_cast<std::size_t>(t)] = (var[static_cast<std::size_t>(t)] / k) / (m * m + floor);
    }
    return err;
}

namespace {

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

// Pixel-weighted mean over tiles.
double tile_mean(const AdaptiveTiles& tiles, const std::vector<double>& v) {
    double sum = 0.0;
    for (int t = 0; t < tiles.count(); ++t) sum += v[static_cast<std::size_t>(t)] * tiles.pixels_in(t);
    return sum / (double(tiles.width) * double(tiles.height));
}

}  // namespace

std::vector<double> adaptive_tile_deviations(const AdaptiveTiles& tiles, const std::vector<PixelSum>& sums,
                                             const std::vector<glm::dvec3>& sum_sq, const std::vector<int>& counts) {
    std::vector<double> var(static_cast<std::size_t>(tiles.count()), 0.0);
    for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * tiles.width + x;
            var[static_cast<std::size_t>(tiles.of_pixel(x, y))] += pixel_moments(sums[p], sum_sq[p], counts[p]).sample_variance;
        }
    for (int t = 0; t < tiles.count(); ++t)
        var[static_cast<std::size_t>(t)] = std::sqrt(var[static_cast<std::size_t>(t)] / tiles.pixels_in(t));
    return var;
}

std::vector<double> adaptive_tile_weights(const AdaptiveTiles& tiles, const std::vector<double>& errors) {
    const std::vector<double> e = capped(errors);
    const double mean_e = tile_mean(tiles, e);
    std::vector<double> w(e.size(), 1.0);
    if (mean_e > 0.0 && std::isfinite(mean_e))
        for (std::size_t t = 0; t < e.size(); ++t) w[t] = kAdaptiveUniformShare + (1.0 - kAdaptiveUniformShare) * e[t] / mean_e;
    return w;
}

std::vector<double> adaptive_pixel_weights(const AdaptiveTiles& tiles, AdaptiveError error, const std::vector<PixelSum>& sums,
                                           const std::vector<glm::dvec3>& sum_sq, int pilot_spp) {
    const std::vector<int> counts(sums.size(), pilot_spp);
    const std::vector<double> tile_w = adaptive_tile_weights(
        tiles, error == AdaptiveError::Relative ? adaptive_tile_errors(tiles, sums, sum_sq, counts)
                                                : adaptive_tile_deviations(tiles, sums, sum_sq, counts));
    std::vector<double> w(sums.size());
    for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x)
            w[static_cast<std::size_t>(y) * tiles.width + x] = tile_w[static_cast<std::size_t>(tiles.of_pixel(x, y))];
    return w;
}

}  // namespace sweeptrace

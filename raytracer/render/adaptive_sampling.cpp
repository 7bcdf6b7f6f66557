#include "raytracer/render/adaptive_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/common.hpp>

namespace sweeptrace {

AdaptiveTiles::AdaptiveTiles(int w, int h)
    : width(w), height(h), tiles_x((w + kAdaptiveTile - 1) / kAdaptiveTile), tiles_y((h + kAdaptiveTile - 1) / kAdaptiveTile) {}

int AdaptiveTiles::pixels_in(int tile) const {
    const int x0 = (tile % tiles_x) * kAdaptiveTile, y0 = (tile / tiles_x) * kAdaptiveTile;
    return (std::min(x0 + kAdaptiveTile, width) - x0) * (std::min(y0 + kAdaptiveTile, height) - y0);
}

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
            const glm::dvec3 m = sum_value(sums[p]) / double(c);
            const double lum = (m.x + m.y + m.z) / 3.0;
            double v = 0.0;
            if (c > 1) {
                const glm::dvec3 s2 = glm::max(sum_sq[p] - double(c) * m * m, glm::dvec3(0.0)) / double(c - 1);
                v = (s2.x + s2.y + s2.z) / 3.0 / double(c);
            }
            const auto t = static_cast<std::size_t>(tiles.of_pixel(x, y));
            var[t] += v;
            mean[t] += lum;
            image_mean += lum;
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

std::vector<int> adaptive_round(const AdaptiveTiles& tiles, const std::vector<double>& errors, std::int64_t budget) {
    const int n = tiles.count();
    const double pixels = double(tiles.width) * double(tiles.height);
    std::vector<int> per_pixel(static_cast<std::size_t>(tiles.width) * tiles.height, 0);
    if (budget <= 0) return per_pixel;
    // The cap: the error at the percentile, by nth_element on a copy (a deterministic order
    // statistic; ties do not matter, the value is the same).
    std::vector<double> sorted(errors);
    const auto k = static_cast<std::size_t>(kAdaptiveCapPercentile * double(n - 1));
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
    const double cap = sorted[k];
    std::vector<double> w(static_cast<std::size_t>(n), 1.0);
    double weighted = 0.0;
    if (cap > 0.0 && std::isfinite(cap)) {
        for (int t = 0; t < n; ++t) w[static_cast<std::size_t>(t)] = std::min(errors[static_cast<std::size_t>(t)], cap);
    }
    for (int t = 0; t < n; ++t) weighted += w[static_cast<std::size_t>(t)] * tiles.pixels_in(t);
    const double mean_w = weighted / pixels;
    // Each tile's samples per pixel, as a real number: the uniform share plus the rest by weight.
    const double per_pixel_avg = double(budget) / pixels;
    std::vector<int> base(static_cast<std::size_t>(n));
    std::vector<double> frac(static_cast<std::size_t>(n));
    std::int64_t given = 0;
    for (int t = 0; t < n; ++t) {
        const double x = per_pixel_avg * (kAdaptiveUniformShare + (1.0 - kAdaptiveUniformShare) * w[static_cast<std::size_t>(t)] / mean_w);
        const double f = std::floor(x);
        base[static_cast<std::size_t>(t)] = static_cast<int>(f);
        frac[static_cast<std::size_t>(t)] = x - f;
        given += static_cast<std::int64_t>(f) * tiles.pixels_in(t);
    }
    // Leftover from the floors goes by largest fractional part; should rounding in x ever make the
    // floors overshoot the budget, samples are taken back from the smallest fractions instead.
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return frac[static_cast<std::size_t>(a)] > frac[static_cast<std::size_t>(b)]; });
    for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x)
            per_pixel[static_cast<std::size_t>(y) * tiles.width + x] = base[static_cast<std::size_t>(tiles.of_pixel(x, y))];
    std::int64_t left = budget - given;
    // Leftover: one more sample per pixel, tile by tile in order of fractional part, pixel by
    // pixel within the last tile reached; repeated (rarely) while samples remain.
    while (left > 0) {
        for (int t : order) {
            const int x0 = (t % tiles.tiles_x) * kAdaptiveTile, y0 = (t / tiles.tiles_x) * kAdaptiveTile;
            for (int y = y0; y < std::min(y0 + kAdaptiveTile, tiles.height) && left > 0; ++y)
                for (int x = x0; x < std::min(x0 + kAdaptiveTile, tiles.width) && left > 0; ++x) {
                    ++per_pixel[static_cast<std::size_t>(y) * tiles.width + x];
                    --left;
                }
            if (left == 0) break;
        }
    }
    while (left < 0) {
        for (int t = static_cast<int>(order.size()) - 1; t >= 0 && left < 0; --t) {
            const int tile = order[static_cast<std::size_t>(t)];
            const int x0 = (tile % tiles.tiles_x) * kAdaptiveTile, y0 = (tile / tiles.tiles_x) * kAdaptiveTile;
            for (int y = y0; y < std::min(y0 + kAdaptiveTile, tiles.height) && left < 0; ++y)
                for (int x = x0; x < std::min(x0 + kAdaptiveTile, tiles.width) && left < 0; ++x) {
                    int& c = per_pixel[static_cast<std::size_t>(y) * tiles.width + x];
                    if (c > 0) {
                        --c;
                        ++left;
                    }
                }
        }
    }
    return per_pixel;
}

}  // namespace sweeptrace

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

std::vector<int> distribute(const AdaptiveTiles& tiles, const std::vector<double>& x, std::int64_t budget);

// A round of `budget` samples: the uniform share evenly, the rest in proportion to each tile's
// weight; returned as whole samples per pixel.
std::vector<int> split_round(const AdaptiveTiles& tiles, const std::vector<double>& weight, std::int64_t budget) {
    const double mean_w = tile_mean(tiles, weight);
    // Each tile's samples per pixel, as a real number.
    const double per_pixel_avg = double(budget) / (double(tiles.width) * double(tiles.height));
    std::vector<double> x(weight.size());
    for (std::size_t t = 0; t < weight.size(); ++t)
        x[t] = per_pixel_avg * (kAdaptiveUniformShare + (1.0 - kAdaptiveUniformShare) * weight[t] / mean_w);
    return distribute(tiles, x, budget);
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

std::vector<int> adaptive_round(const AdaptiveTiles& tiles, const std::vector<double>& errors, std::int64_t budget) {
    if (budget <= 0) return std::vector<int>(static_cast<std::size_t>(tiles.width) * tiles.height, 0);
    return split_round(tiles, capped(errors), budget);
}

std::vector<int> adaptive_round_mse(const AdaptiveTiles& tiles, const std::vector<double>& deviations,
                                    const std::vector<int>& counts, std::int64_t budget) {
    const int n = tiles.count();
    const double pixels = double(tiles.width) * double(tiles.height);
    if (budget <= 0) return std::vector<int>(static_cast<std::size_t>(tiles.width) * tiles.height, 0);
    const std::vector<double> sigma = capped(deviations);
    const double mean_sigma = tile_mean(tiles, sigma);
    std::vector<double> have(static_cast<std::size_t>(n), 0.0);
    std::int64_t spent = 0;
    for (int y = 0; y < tiles.height; ++y)
        for (int xx = 0; xx < tiles.width; ++xx) {
            const int c = counts[static_cast<std::size_t>(y) * tiles.width + xx];
            have[static_cast<std::size_t>(tiles.of_pixel(xx, y))] += c;
            spent += c;
        }
    const double after = double(spent + budget) / pixels;  // mean samples per pixel after the round
    std::vector<double> shortfall(static_cast<std::size_t>(n));
    for (int t = 0; t < n; ++t) {
        const double want = after * sigma[static_cast<std::size_t>(t)] / mean_sigma;
        shortfall[static_cast<std::size_t>(t)] = std::max(0.0, want - have[static_cast<std::size_t>(t)] / tiles.pixels_in(t));
    }
    // Every tile at or above its share: by sigma, as a fresh start would.
    return split_round(tiles, tile_mean(tiles, shortfall) > 0.0 ? shortfall : sigma, budget);
}

namespace {

// Whole samples per pixel from each tile's real number x_t, exactly `budget` in all: the floors,
// then the leftover by largest fractional part (see adaptive_round).
std::vector<int> distribute(const AdaptiveTiles& tiles, const std::vector<double>& x, std::int64_t budget) {
    const int n = tiles.count();
    std::vector<int> per_pixel(static_cast<std::size_t>(tiles.width) * tiles.height, 0);
    std::vector<int> base(static_cast<std::size_t>(n));
    std::vector<double> frac(static_cast<std::size_t>(n));
    std::int64_t given = 0;
    for (int t = 0; t < n; ++t) {
        const double f = std::floor(x[static_cast<std::size_t>(t)]);
        base[static_cast<std::size_t>(t)] = static_cast<int>(f);
        frac[static_cast<std::size_t>(t)] = x[static_cast<std::size_t>(t)] - f;
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

}  // namespace

}  // namespace sweeptrace

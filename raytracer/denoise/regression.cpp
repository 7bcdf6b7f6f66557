// Collaborative regression (regression.hpp), tile by tile: the NL-means weights of every centre
// of the tile against each of its window's offsets are computed offset by offset (as nl_means
// does), then each centre's normal equations are summed in double, solved
// (least_squares.hpp), and its prediction over its window added to the tile's own accumulation
// buffer (the tile grown by R), which is merged into the image after all tiles, in tile order.
#include "raytracer/denoise/regression.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <cmath>
#include <vector>

#include "raytracer/denoise/least_squares.hpp"
#include "raytracer/denoise/tiles.hpp"

namespace sweeptrace::denoise {
namespace {

struct TileResult {
    Rect area;                   // the tile grown by R, clipped to the image
    std::vector<float> sum;      // 3 channels x area pixels: weighted predictions
    std::vector<float> weights;  // area pixels
};

// What one centre's fit reads and where it adds its prediction.
struct Window {
    const Planes& image;
    const Planes& features;
    const float* weight;  // [offset * n + centre index in the tile]
    std::size_t n;        // the tile's pixels
    int r;
    TileResult& res;
};

// The fit of the window around (cx, cy): its normal equations in double, solved, and its
// prediction added, weighted, to every pixel of the window. `Terms` (1, dx, dy, the features) is
// a template parameter so that the inner products unroll: they are half of NFOR's time.
template <int Terms>
void fit_centre(const Window& win, int cx, int cy, std::size_t ci) {
    const Planes& image = win.image;
    const int w = image.width, h = image.height, r = win.r, side = 2 * r + 1;
    const std::size_t centre = std::size_t(cy) * std::size_t(w) + std::size_t(cx);
    double a[kMaxRegressionTerms * kMaxRegressionTerms] = {}, b[kMaxRegressionTerms * 3] = {}, beta[kMaxRegressionTerms * 3];
    double x_row[kMaxRegressionTerms];
    const int x0 = std::max(cx - r, 0), x1 = std::min(cx + r + 1, w), y0 = std::max(cy - r, 0), y1 = std::min(cy + r + 1, h);
    auto fill_row = [&](int x, int y) {
        const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
        x_row[0] = 1.0;
        x_row[1] = x - cx;
        x_row[2] = y - cy;
        for (int f = 0; f + 3 < Terms; ++f) x_row[3 + f] = double(win.features.channel(f)[p]) - win.features.channel(f)[centre];
    };
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const double wt = win.weight[std::size_t((y - cy + r) * side + (x - cx + r)) * win.n + ci];
            if (wt == 0.0) continue;
            fill_row(x, y);
            const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const double rgb[3] = {image.channel(0)[p], image.channel(1)[p], image.channel(2)[p]};
            for (int i = 0; i < Terms; ++i) {
                const double wx = wt * x_row[i];
                for (int j = 0; j <= i; ++j) a[i * Terms + j] += wx * x_row[j];
                for (int c = 0; c < 3; ++c) b[i * 3 + c] += wx * rgb[c];
            }
        }
    for (int i = 0; i < Terms; ++i)
        for (int j = 0; j < i; ++j) a[j * Terms + i] = a[i * Terms + j];
    solve_normal_equations(a, b, Terms, beta);
    TileResult& res = win.res;
    const std::size_t area_w = std::size_t(res.area.width()), area_n = res.weights.size();
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const float wt = win.weight[std::size_t((y - cy + r) * side + (x - cx + r)) * win.n + ci];
            if (wt == 0.0f) continue;
            fill_row(x, y);
            const std::size_t q = std::size_t(y - res.area.y0) * area_w + std::size_t(x - res.area.x0);
            for (int c = 0; c < 3; ++c) {
                double pred = 0.0;
                for (int i = 0; i < Terms; ++i) pred += x_row[i] * beta[i * 3 + c];
                res.sum[std::size_t(c) * area_n + q] += wt * float(pred);
            }
            res.weights[q] += wt;
        }
}

using FitFn = void (*)(const Window&, int, int, std::size_t);

template <int... T>
constexpr std::array<FitFn, sizeof...(T)> fit_table(std::integer_sequence<int, T...>) {
    return {&fit_centre<T>...};
}

// fit_centre for every number of terms, by index (0 to 2 are never used: the offset terms are always there).
constexpr auto kFits = fit_table(std::make_integer_sequence<int, kMaxRegressionTerms + 1>());

}  // namespace

Planes collaborative_regression(const Planes& image, const Planes& guide, const Planes& guide_variance, const Planes& features,
                                const RegressionParams& params) {
    const int w = image.width, h = image.height, r = params.search_radius, side = 2 * r + 1;
    const int terms = 3 + features.channels;  // 1, dx, dy, the features
    if (terms > kMaxRegressionTerms)
        throw std::logic_error("collaborative_regression: " + std::to_string(features.channels) + " features, at most " +
                               std::to_string(kMaxRegressionTerms - 3));
    const NlMeansParams weight_params{params.patch_radius, r, params.k, params.variance_scale};
    const std::vector<Rect> tiles = image_tiles(w, h);
    std::vector<TileResult> results(tiles.size());
    for_each_tile(tiles, [&](std::size_t index, const Rect& tile) {
        const std::size_t n = std::size_t(tile.width()) * std::size_t(tile.height());
        // weight[(offset) * n + centre]: the largest channel distance decides (a window pixel must
        // resemble the centre in every channel).
        std::vector<float> weight(std::size_t(side) * std::size_t(side) * n, 0.0f), dist;
        PatchScratch scratch;
        for (int dy = -r, o = 0; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx, ++o) {
                const Rect out = patch_distances(guide, guide_variance, weight_params, tile, dx, dy, scratch, dist);
                for (int y = out.y0; y < out.y1; ++y)
                    for (int x = out.x0; x < out.x1; ++x) {
                        const std::size_t i = std::size_t(y - tile.y0) * std::size_t(tile.width()) + std::size_t(x - tile.x0);
                        float d = dist[i];
                        for (int c = 1; c < guide.channels; ++c) d = std::max(d, dist[std::size_t(c) * n + i]);
                        weight[std::size_t(o) * n + i] = std::exp(-std::max(d, 0.0f));
                    }
            }
        TileResult& res = results[index];
        res.area = {std::max(tile.x0 - r, 0), std::max(tile.y0 - r, 0), std::min(tile.x1 + r, w), std::min(tile.y1 + r, h)};
        const std::size_t area_w = std::size_t(res.area.width());
        res.sum.assign(3 * area_w * std::size_t(res.area.height()), 0.0f);
        res.weights.assign(area_w * std::size_t(res.area.height()), 0.0f);
        const Window window{image, features, weight.data(), n, r, res};
        const FitFn fit = kFits[std::size_t(terms)];
        for (int cy = tile.y0; cy < tile.y1; ++cy)
            for (int cx = tile.x0; cx < tile.x1; ++cx)
                fit(window, cx, cy, std::size_t(cy - tile.y0) * std::size_t(tile.width()) + std::size_t(cx - tile.x0));
    });
    Planes sum(w, h, 3);
    std::vector<float> weights(std::size_t(w) * std::size_t(h), 0.0f);
    for (const TileResult& res : results) {
        const std::size_t area_w = std::size_t(res.area.width()), area_n = res.weights.size();
        for (int y = res.area.y0; y < res.area.y1; ++y)
            for (int x = res.area.x0; x < res.area.x1; ++x) {
                const std::size_t q = std::size_t(y - res.area.y0) * area_w + std::size_t(x - res.area.x0);
                const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
                for (int c = 0; c < 3; ++c) sum.channel(c)[p] += res.sum[std::size_t(c) * area_n + q];
                weights[p] += res.weights[q];
            }
    }
    // Every pixel is its own window's centre with weight 1 (distance <= 0 to itself).
    for (int c = 0; c < 3; ++c)
        for (std::size_t p = 0; p < weights.size(); ++p) sum.channel(c)[p] /= weights[p];
    return sum;
}

}  // namespace sweeptrace::denoise

// Collaborative regression (regression.hpp), tile by tile. The NL-means distances of every
// centre of the tile to each of its window's offsets are computed offset by offset (as nl_means
// does), once for all bandwidths. Then, per bandwidth, one row of centres at a time, the normal equations of all the row's windows are
// summed together, offset by offset, each sum a float lane per centre: the loops run along the row
// and vectorize, and every lane does the same operations in the same order whatever the vector
// width. A window row's 2R + 1 products are summed in float and the rows' sums in double, so an
// entry's relative rounding stays below (2R + 3) float epsilons, the precision the solve
// (least_squares.hpp) is told. Each centre's fit predicts every pixel of its window into the
// tile's own accumulation buffer (the tile grown by R), merged into the image after all tiles, in
// tile order.
#include "raytracer/denoise/regression.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "raytracer/denoise/exp_weight.hpp"
#include "raytracer/denoise/least_squares.hpp"
#include "raytracer/denoise/tiles.hpp"

namespace sweeptrace::denoise {
namespace {

constexpr int kLanes = kTileSize;  // a row of centres; lanes past the tile's width have weight 0

struct TileResult {
    Rect area;                   // the tile grown by R, clipped to the image
    std::vector<float> sum;      // 3 channels x area pixels: weighted predictions
    std::vector<float> weights;  // area pixels
};

// A tile's inputs and working buffers. The image and features are copied over the tile grown by R
// with zeros outside the image (`local`, row stride kLanes + 2R), so a window's row is read as a
// plain slice whatever the border: its pixels outside the image have weight 0.
struct TileWork {
    Rect tile;
    int r = 0;
    int stride = 0;                // kLanes + 2R
    std::vector<float> local;      // [channel (features, then 3 colours)][row][stride]
    std::vector<float> weight;     // [offset][tile row][kLanes]
    std::vector<float> beta;       // [term][colour][kLanes] of the current row of centres

    const float* local_row(int channel, int y) const {
        return local.data() + (std::size_t(channel) * std::size_t(tile.height() + 2 * r) + std::size_t(y - tile.y0 + r)) * std::size_t(stride);
    }
};

// The terms of one window pixel for every centre of a row: x[t][lane], t = 1, dx, dy, then the
// features relative to the centre's.
template <int Terms>
[[gnu::always_inline]] inline void fill_terms(const TileWork& work, int cy, int dx, int dy, float (&x)[Terms][kLanes]) {
    const int r = work.r;
    for (int i = 0; i < kLanes; ++i) {
        x[0][i] = 1.0f;
        x[1][i] = float(dx);
        x[2][i] = float(dy);
    }
    for (int t = 3; t < Terms; ++t) {
        const float* window = work.local_row(t - 3, cy + dy) + r + dx;
        const float* centre = work.local_row(t - 3, cy) + r;
        for (int i = 0; i < kLanes; ++i) x[t][i] = window[i] - centre[i];
    }
}

// Fits the windows of the tile's row of centres cy and adds their predictions to `res`.
template <int Terms>
[[gnu::always_inline]] inline void fit_row(TileWork& work, int cy, TileResult& res) {
    constexpr int kPairs = Terms * (Terms + 1) / 2, kEntries = kPairs + 3 * Terms;
    const int r = work.r, side = 2 * r + 1, width = work.tile.width();
    const int features = Terms - 3;
    const std::size_t row_offset = std::size_t(cy - work.tile.y0) * kLanes, offset_stride = std::size_t(kTileSize) * kLanes;
    // The normal equations' lower triangle (pair j >= k at j (j + 1) / 2 + k) and right-hand
    // sides (at kPairs + 3 j + c), per lane.
    alignas(32) float window_row[kEntries][kLanes];
    alignas(32) double total[kEntries][kLanes] = {};
    alignas(32) float x[Terms][kLanes], wx[Terms][kLanes];
    // Term 2 (dy) is constant along a window row, so its entries are taken from the row's sums of
    // term 0 (1) once per row: sum w x_j dy = dy sum w x_j. Products with term 0 are additions.
    auto pair = [](int j, int k) { return j * (j + 1) / 2 + k; };  // j >= k
    for (int dy = -r; dy <= r; ++dy) {
        for (auto& e : window_row) std::fill(e, e + kLanes, 0.0f);
        for (int dx = -r; dx <= r; ++dx) {
            const float* w = work.weight.data() + std::size_t((dy + r) * side + dx + r) * offset_stride + row_offset;
            fill_terms<Terms>(work, cy, dx, dy, x);
            for (int t = 0; t < Terms; ++t)
                for (int i = 0; i < kLanes; ++i) wx[t][i] = w[i] * x[t][i];
            for (int j = 0; j < Terms; ++j) {
                if (j == 2) continue;
                for (int i = 0; i < kLanes; ++i) window_row[pair(j, 0)][i] += wx[j][i];
                for (int k = 1; k <= j; ++k)
                    if (k != 2)
                        for (int i = 0; i < kLanes; ++i) window_row[pair(j, k)][i] += wx[j][i] * x[k][i];
            }
            for (int c = 0; c < 3; ++c) {
                const float* colour = work.local_row(features + c, cy + dy) + r + dx;
                for (int j = 0; j < Terms; ++j)
                    if (j != 2)
                        for (int i = 0; i < kLanes; ++i) window_row[kPairs + 3 * j + c][i] += wx[j][i] * colour[i];
            }
        }
        const double ddy = dy;
        for (int e = 0; e < kEntries; ++e)
            for (int i = 0; i < kLanes; ++i) total[e][i] += double(window_row[e][i]);
        for (int j = 0; j < Terms; ++j)
            if (j != 2)
                for (int i = 0; i < kLanes; ++i) total[j > 2 ? pair(j, 2) : pair(2, j)][i] += ddy * double(window_row[pair(j, 0)][i]);
        for (int i = 0; i < kLanes; ++i) total[pair(2, 2)][i] += ddy * ddy * double(window_row[pair(0, 0)][i]);
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < kLanes; ++i) total[kPairs + 3 * 2 + c][i] += ddy * double(window_row[kPairs + c][i]);
    }
    // Each centre's solve.
    const double precision = (2 * r + 3) * double(FLT_EPSILON);
    for (int i = 0; i < width; ++i) {
        double a[Terms * Terms], b[Terms * 3], beta[Terms * 3];
        for (int j = 0; j < Terms; ++j)
            for (int k = 0; k <= j; ++k) a[j * Terms + k] = a[k * Terms + j] = total[pair(j, k)][i];
        for (int e = 0; e < 3 * Terms; ++e) b[e] = total[kPairs + e][i];
        solve_normal_equations(a, b, Terms, beta, precision);
        for (int e = 0; e < 3 * Terms; ++e) work.beta[std::size_t(e) * kLanes + std::size_t(i)] = float(beta[e]);
    }
    // The predictions: every window pixel gets its centre's fit, weighted.
    const std::size_t area_w = std::size_t(res.area.width()), area_n = res.weights.size();
    for (int dy = -r; dy <= r; ++dy) {
        const int y = cy + dy;
        if (y < res.area.y0 || y >= res.area.y1) continue;
        for (int dx = -r; dx <= r; ++dx) {
            const float* w = work.weight.data() + std::size_t((dy + r) * side + dx + r) * offset_stride + row_offset;
            fill_terms<Terms>(work, cy, dx, dy, x);
            // The window pixels of lanes 0 .. width - 1, those outside the image (weight 0) included:
            // columns tile.x0 + dx .. tile.x1 + dx - 1, clipped to the area.
            const int lane0 = std::max(0, res.area.x0 - (work.tile.x0 + dx)), lane1 = std::min(width, res.area.x1 - (work.tile.x0 + dx));
            const std::size_t q0 = std::size_t(y - res.area.y0) * area_w + std::size_t(work.tile.x0 + dx + lane0 - res.area.x0);
            for (int c = 0; c < 3; ++c) {
                float pred[kLanes];
                for (int i = 0; i < kLanes; ++i) pred[i] = 0.0f;
                for (int t = 0; t < Terms; ++t) {
                    const float* bt = work.beta.data() + std::size_t(3 * t + c) * kLanes;
                    for (int i = 0; i < kLanes; ++i) pred[i] += x[t][i] * bt[i];
                }
                float* sum = res.sum.data() + std::size_t(c) * area_n + q0;
                for (int i = lane0; i < lane1; ++i) sum[i - lane0] += w[i] * pred[i];
            }
            float* weights = res.weights.data() + q0;
            for (int i = lane0; i < lane1; ++i) weights[i - lane0] += w[i];
        }
    }
}

// The loops, inlined into one function per instruction set (filter_isa.hpp).
template <int Terms>
void fit_row_baseline(TileWork& work, int cy, TileResult& res) {
    fit_row<Terms>(work, cy, res);
}

template <int Terms>
[[gnu::target("avx2")]] void fit_row_avx2(TileWork& work, int cy, TileResult& res) {
    fit_row<Terms>(work, cy, res);
}

using FitRowFn = void (*)(TileWork&, int, TileResult&);

template <int... T>
constexpr std::array<FitRowFn, sizeof...(T)> fit_table(std::integer_sequence<int, T...>, FilterIsa isa) {
    if (isa == FilterIsa::Avx2) return {&fit_row_avx2<T + 3>...};
    return {&fit_row_baseline<T + 3>...};
}

// fit_row for every number of terms from 3 (the offset terms alone) up, at index terms - 3.
constexpr auto kFitsBaseline = fit_table(std::make_integer_sequence<int, kMaxRegressionTerms - 2>(), FilterIsa::Baseline);
constexpr auto kFitsAvx2 = fit_table(std::make_integer_sequence<int, kMaxRegressionTerms - 2>(), FilterIsa::Avx2);

// The weights exp(-d / k^2) of a tile's distances.
[[gnu::always_inline]] inline void weights_of(const std::vector<float>& distance, float scale, std::vector<float>& weight) {
    for (std::size_t i = 0; i < weight.size(); ++i) weight[i] = exp_weight(distance[i] * scale);
}

void weights_baseline(const std::vector<float>& distance, float scale, std::vector<float>& weight) { weights_of(distance, scale, weight); }

[[gnu::target("avx2")]] void weights_avx2(const std::vector<float>& distance, float scale, std::vector<float>& weight) {
    weights_of(distance, scale, weight);
}

}  // namespace

std::vector<Planes> collaborative_regression(const Planes& image, const Planes& guide, const Planes& guide_variance, const Planes& features,
                                             const RegressionParams& params, const std::vector<float>& bandwidths, FilterIsa isa) {
    const int w = image.width, h = image.height, r = params.search_radius, side = 2 * r + 1;
    const int terms = 3 + features.channels;  // 1, dx, dy, the features
    if (terms > kMaxRegressionTerms)
        throw std::logic_error("collaborative_regression: " + std::to_string(features.channels) + " features, at most " +
                               std::to_string(kMaxRegressionTerms - 3));
    // The distances at k = 1; at bandwidth k they are these over k^2 (nl_means.hpp).
    const NlMeansParams distance_params{params.patch_radius, r, 1.0f, params.variance_scale};
    const std::vector<Rect> tiles = image_tiles(w, h);
    std::vector<std::vector<TileResult>> results(bandwidths.size(), std::vector<TileResult>(tiles.size()));
    for_each_tile(tiles, [&](std::size_t index, const Rect& tile) {
        const std::size_t n = std::size_t(tile.width()) * std::size_t(tile.height());
        TileWork work;
        work.tile = tile;
        work.r = r;
        work.stride = kLanes + 2 * r;
        // distance[offset][row][lane]: the largest channel distance decides (a window pixel must
        // resemble the centre in every channel); infinite where the window pixel is outside the
        // image (weight 0).
        const std::size_t offset_stride = std::size_t(kTileSize) * kLanes, weights_size = std::size_t(side) * std::size_t(side) * offset_stride;
        std::vector<float> distance(weights_size, std::numeric_limits<float>::infinity()), dist;
        PatchScratch scratch;
        for (int dy = -r, o = 0; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx, ++o) {
                const Rect out = patch_distances(guide, guide_variance, distance_params, tile, dx, dy, scratch, dist, isa);
                for (int y = out.y0; y < out.y1; ++y) {
                    const std::size_t from = std::size_t(y - tile.y0) * std::size_t(tile.width()) + std::size_t(out.x0 - tile.x0);
                    float* to = distance.data() + std::size_t(o) * offset_stride + std::size_t(y - tile.y0) * kLanes + std::size_t(out.x0 - tile.x0);
                    for (int i = 0; i < out.width(); ++i) to[i] = dist[from + std::size_t(i)];
                    for (int c = 1; c < guide.channels; ++c)
                        for (int i = 0; i < out.width(); ++i) to[i] = std::max(to[i], dist[std::size_t(c) * n + from + std::size_t(i)]);
                }
            }
        // The features, then the colour, over the tile grown by R (zero outside the image).
        const int rows = tile.height() + 2 * r;
        work.local.assign(std::size_t(features.channels + 3) * std::size_t(rows) * std::size_t(work.stride), 0.0f);
        for (int ch = 0; ch < features.channels + 3; ++ch) {
            const float* src = ch < features.channels ? features.channel(ch) : image.channel(ch - features.channels);
            for (int y = std::max(tile.y0 - r, 0); y < std::min(tile.y1 + r, h); ++y) {
                float* dst = const_cast<float*>(work.local_row(ch, y));
                for (int x = std::max(tile.x0 - r, 0); x < std::min(tile.x0 + kLanes + r, w); ++x) dst[x - tile.x0 + r] = src[std::size_t(y) * std::size_t(w) + std::size_t(x)];
            }
        }
        work.weight.resize(weights_size);
        for (std::size_t b = 0; b < bandwidths.size(); ++b) {
            const float scale = 1.0f / (bandwidths[b] * bandwidths[b]);
            (isa == FilterIsa::Avx2 ? weights_avx2 : weights_baseline)(distance, scale, work.weight);
            work.beta.assign(std::size_t(3 * terms) * kLanes, 0.0f);
            TileResult& res = results[b][index];
            res.area = {std::max(tile.x0 - r, 0), std::max(tile.y0 - r, 0), std::min(tile.x1 + r, w), std::min(tile.y1 + r, h)};
            const std::size_t area_w = std::size_t(res.area.width());
            res.sum.assign(3 * area_w * std::size_t(res.area.height()), 0.0f);
            res.weights.assign(area_w * std::size_t(res.area.height()), 0.0f);
            const FitRowFn fit = (isa == FilterIsa::Avx2 ? kFitsAvx2 : kFitsBaseline)[std::size_t(terms - 3)];
            for (int cy = tile.y0; cy < tile.y1; ++cy) fit(work, cy, res);
        }
    });
    std::vector<Planes> out;
    for (const std::vector<TileResult>& tile_results : results) {
        Planes sum(w, h, 3);
        std::vector<float> weights(std::size_t(w) * std::size_t(h), 0.0f);
        for (const TileResult& res : tile_results) {
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
        out.push_back(std::move(sum));
    }
    return out;
}

}  // namespace sweeptrace::denoise

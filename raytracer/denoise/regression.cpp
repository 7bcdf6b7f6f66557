// Collaborative regression (regression.hpp), tile by tile. The NL-means distances of every
// centre of the tile to each of its window's offsets are computed offset by offset (as nl_means
// does), once for all bandwidths. Then, one row of centres at a time, for two bandwidths at once
// (the loads of the window's terms and colours shared), the normal equations of all the row's
// windows are summed together, offset by offset, each sum a float lane per centre (the solves
// too, least_squares_lanes.hpp): the loops run along the row
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

#include <tbb/enumerable_thread_specific.h>

#include "raytracer/denoise/exp_weight.hpp"
#include "raytracer/denoise/float_vector.hpp"
#include "raytracer/denoise/least_squares.hpp"
#include "raytracer/denoise/least_squares_lanes.hpp"
#include "raytracer/denoise/tiles.hpp"

namespace sweeptrace::denoise {
namespace {

constexpr int kLanes = kTileSize;  // a row of centres; lanes past the tile's width have weight 0

struct TileResult {
    Rect area;                   // the rows of the tile grown by R, clipped to the image; columns below
    int stride = 0;              // kLanes + 2R: columns tile.x0 - R .. tile.x0 + kLanes + R, unclipped
    std::vector<float> sum;      // 3 channels x area rows x stride: weighted predictions
    std::vector<float> weights;  // area rows x stride

    // Column 0 of row y's buffer, channel c (3: the weights).
    float* row(int c, int y) {
        float* base = c < 3 ? sum.data() + std::size_t(c) * weights.size() : weights.data();
        return base + std::size_t(y - area.y0) * std::size_t(stride);
    }
};

// A tile's inputs and working buffers. The image and features are copied over the tile grown by R
// with zeros outside the image (`local`, row stride kLanes + 2R), so a window's row is read as a
// plain slice whatever the border: its pixels outside the image have weight 0. The buffers the
// row fits read a register at a time start a cache line (AlignedFloats), so those loads (the
// weights' and terms', each row of kLanes floats a whole number of lines) never cross one.
struct TileWork {
    Rect tile;
    int r = 0;
    int stride = 0;                // kLanes + 2R
    std::vector<float> local;      // [channel (features, then 3 colours)][row][stride]
    AlignedFloats weight;          // [bandwidth][offset][kLanes] of the current row of centres
    std::size_t band_stride = 0;   // one bandwidth's part of `weight` (and the next one's start)
    AlignedFloats beta;            // [bandwidth][term][colour][kLanes] of the current row of centres
    AlignedFloats terms;           // [feature][dx + R][kLanes]: one window row's feature terms
    std::vector<float> products;   // [colour or weight][dx + R][2R + kLanes + 2R]: predict_row's

    const float* local_row(int channel, int y) const {
        return local.data() + (std::size_t(channel) * std::size_t(tile.height() + 2 * r) + std::size_t(y - tile.y0 + r)) * std::size_t(stride);
    }
};

// Row dy of the windows of a row of centres cy, as the kernels read it. For lane i (centre
// (tile.x0 + i, cy)) and offset dx: bandwidth b's weight at weight[b * band_stride + (dx + R) *
// kLanes + i], feature f's
// term (the window pixel's value less the centre's) at terms[(f * side + dx + R) * kLanes + i], and
// colour c at colour[c][dx + R + i].
struct WindowRow {
    int r = 0, side = 0;
    float dy = 0.0f;
    const float* weight = nullptr;
    std::size_t band_stride = 0;
    const float* terms = nullptr;
    const float* colour[3] = {};

    const float* term(int f, int dx) const { return terms + (std::size_t(f) * std::size_t(side) + std::size_t(dx + r)) * kLanes; }
};

// Fills work.terms with row dy of the windows of centres cy, and returns its view.
[[gnu::always_inline]] inline WindowRow window_row_of(TileWork& work, int features, int cy, int dy) {
    const int r = work.r, side = 2 * r + 1;
    for (int f = 0; f < features; ++f) {
        const float* centre = work.local_row(f, cy) + r;
        const float* window = work.local_row(f, cy + dy);
        for (int o = 0; o < side; ++o) {
            float* t = work.terms.data() + (std::size_t(f) * std::size_t(side) + std::size_t(o)) * kLanes;
            for (int i = 0; i < kLanes; ++i) t[i] = window[o + i] - centre[i];
        }
    }
    WindowRow row;
    row.r = r;
    row.side = side;
    row.dy = float(dy);
    row.weight = work.weight.data() + std::size_t((dy + r) * side) * kLanes;
    row.band_stride = work.band_stride;
    row.terms = work.terms.data();
    for (int c = 0; c < 3; ++c) row.colour[c] = work.local_row(features + c, cy + dy);
    return row;
}

// One block of the normal equations' sums over a window row: the entries of term J (J != 2, whose
// entries come from the row's sums, below) with the terms k <= J (k != 2) and with the three
// colours, summed over dx in registers, one vector of lanes at a time, for B bandwidths at once
// (bandwidth b's entries at window_row[b * entries + e]): the terms and colours are loaded once
// for all of them. The products are those of a scalar loop, in the same order: w x_J first, then
// times x_k; the sum starts at 0 and runs over dx = -R .. R.
template <int Terms, class V, int J, int B>
[[gnu::always_inline]] inline void sum_block(const WindowRow& row, float (*window_row)[kLanes]) {
    if constexpr (J != 2) {
        constexpr int kPairs = Terms * (Terms + 1) / 2, kEntries = kPairs + 3 * Terms;
        constexpr int kProducts = J < 2 ? J + 1 : J;  // k = 0, 1, 3 .. J
        constexpr int L = kVectorLanes<V>;
        const int r = row.r;
        for (int lane = 0; lane < kLanes; lane += L) {
            V acc[B][kProducts + 3];
#pragma GCC unroll 2
            for (int b = 0; b < B; ++b)
#pragma GCC unroll 32
                for (V& a : acc[b]) a = V{};
            for (int dx = -r; dx <= r; ++dx) {
                const V x_dx = broadcast<V>(float(dx));
                V wx[B];
#pragma GCC unroll 2
                for (int b = 0; b < B; ++b) {
                    const V w = load_floats<V>(row.weight + std::size_t(b) * row.band_stride + std::size_t(dx + r) * kLanes + std::size_t(lane));
                    if constexpr (J == 0)
                        wx[b] = w;  // w times the constant term 1
                    else if constexpr (J == 1)
                        wx[b] = w * x_dx;
                    else
                        wx[b] = w * load_floats<V>(row.term(J - 3, dx) + lane);
                    acc[b][0] += wx[b];
                    if constexpr (J >= 1) acc[b][1] += wx[b] * x_dx;
                }
#pragma GCC unroll 16
                for (int k = 3; k <= J; ++k) {
                    const V x = load_floats<V>(row.term(k - 3, dx) + lane);
#pragma GCC unroll 2
                    for (int b = 0; b < B; ++b) acc[b][k - 1] += wx[b] * x;
                }
#pragma GCC unroll 3
                for (int c = 0; c < 3; ++c) {
                    const V colour = load_floats<V>(row.colour[c] + dx + r + lane);
#pragma GCC unroll 2
                    for (int b = 0; b < B; ++b) acc[b][kProducts + c] += wx[b] * colour;
                }
            }
            constexpr int base = J * (J + 1) / 2;  // pair (J, 0)
#pragma GCC unroll 2
            for (int b = 0; b < B; ++b) {
                float(*entries)[kLanes] = window_row + b * kEntries;
                store_floats(entries[base] + lane, acc[b][0]);
                if constexpr (J >= 1) store_floats(entries[base + 1] + lane, acc[b][1]);
#pragma GCC unroll 16
                for (int k = 3; k <= J; ++k) store_floats(entries[base + k] + lane, acc[b][k - 1]);
#pragma GCC unroll 3
                for (int c = 0; c < 3; ++c) store_floats(entries[kPairs + 3 * J + c] + lane, acc[b][kProducts + c]);
            }
        }
    }
}

template <int Terms, class V, int B, int... J>
[[gnu::always_inline]] inline void sum_blocks(const WindowRow& row, float (*window_row)[kLanes], std::integer_sequence<int, J...>) {
    (sum_block<Terms, V, J, B>(row, window_row), ...);
}

// The predictions of a row of centres' fits for window row dy, added to the tile's buffers (sum:
// column 0 of the window row's buffer row per colour, the weights' row at sum[3]). First every
// lane's weighted prediction w (beta . x) at every dx, with the fit (beta, [term][colour][kLanes])
// held in registers, into `products` ([colour or weight][dx + R][2R + kLanes + 2R], lane i at 2R + i,
// zero around); then each buffer column, a vector of columns at a time, adds the products that
// fall on it in the order of dx, in registers: the order of a scalar loop over dx and lanes, so
// the same bits whatever the vector width (the lanes outside 0 .. kLanes add +0, which changes
// no sum).
template <int Terms, class V>
[[gnu::always_inline]] inline void predict_row(const WindowRow& row, const float* weight, const float* beta, float* products,
                                               float* const (&sum)[4]) {
    constexpr int L = kVectorLanes<V>;
    const int r = row.r, side = row.side, padded = kLanes + 4 * r, columns = kLanes + 2 * r;
    const V y_dy = broadcast<V>(row.dy);
    auto product = [&](int c, int dx) { return products + std::size_t(c * side + dx + r) * std::size_t(padded) + std::size_t(2 * r); };
    for (int lane = 0; lane < kLanes; lane += L) {
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) {
            V b[Terms];
#pragma GCC unroll 16
            for (int t = 0; t < Terms; ++t) b[t] = load_floats<V>(beta + std::size_t(3 * t + c) * kLanes + std::size_t(lane));
            for (int dx = -r; dx <= r; ++dx) {
                // 0 + 1 b_0 + dx b_1 + dy b_2 + the features' terms
                V pred = V{} + b[0];
                pred += broadcast<V>(float(dx)) * b[1];
                pred += y_dy * b[2];
#pragma GCC unroll 16
                for (int t = 3; t < Terms; ++t) pred += load_floats<V>(row.term(t - 3, dx) + lane) * b[t];
                const V w = load_floats<V>(weight + std::size_t(dx + r) * kLanes + std::size_t(lane));
                store_floats(product(c, dx) + lane, w * pred);
            }
        }
        for (int dx = -r; dx <= r; ++dx)
            store_floats(product(3, dx) + lane, load_floats<V>(weight + std::size_t(dx + r) * kLanes + std::size_t(lane)));
    }
    // Column q of the buffer holds the window pixels of lane q - (dx + R) at offset dx.
    for (int c = 0; c < 4; ++c) {
        int q = 0;
        for (; q + L <= columns; q += L) {
            V acc = load_floats<V>(sum[c] + q);
            for (int dx = -r; dx <= r; ++dx) acc += load_floats<V>(product(c, dx) + q - (dx + r));
            store_floats(sum[c] + q, acc);
        }
        for (; q < columns; ++q) {
            float acc = sum[c][q];
            for (int dx = -r; dx <= r; ++dx) acc += product(c, dx)[q - (dx + r)];
            sum[c][q] = acc;
        }
    }
}

// Fits the windows of the tile's row of centres cy, for B bandwidths at once (weights in
// work.weight, bandwidth b's at b * band_stride), and adds bandwidth b's predictions to res[b].
template <int Terms, FilterIsa Isa, int B>
[[gnu::always_inline]] inline void fit_row(TileWork& work, int cy, TileResult* const* res) {
    using V = FloatVector<Isa>;
    static_assert(kLanes % kVectorLanes<V> == 0);
    constexpr int kPairs = Terms * (Terms + 1) / 2, kEntries = kPairs + 3 * Terms;
    const int r = work.r, width = work.tile.width();
    const int features = Terms - 3;
    // The normal equations' lower triangle (pair j >= k at j (j + 1) / 2 + k) and right-hand
    // sides (at kPairs + 3 j + c), per bandwidth and lane: a window row's sums in float (bandwidth
    // b's at b * kEntries), their total in double. The entries with term 2 (dy) are not summed per
    // row (they stay 0 there): dy is constant along a window row, so sum w x_j dy = dy sum w x_j
    // is taken from the row's sums of term 0 (1).
    alignas(64) float window_row[B * kEntries][kLanes] = {};
    alignas(64) double total[B][kEntries][kLanes] = {};
    auto pair = [](int j, int k) { return j * (j + 1) / 2 + k; };  // j >= k
    for (int dy = -r; dy <= r; ++dy) {
        const WindowRow row = window_row_of(work, features, cy, dy);
        sum_blocks<Terms, V, B>(row, window_row, std::make_integer_sequence<int, Terms>());
        const double ddy = dy;
        for (int b = 0; b < B; ++b) {
            const float(*sums)[kLanes] = window_row + b * kEntries;
            double(*t)[kLanes] = total[b];
            for (int e = 0; e < kEntries; ++e)
                for (int i = 0; i < kLanes; ++i) t[e][i] += double(sums[e][i]);
            for (int j = 0; j < Terms; ++j)
                if (j != 2)
                    for (int i = 0; i < kLanes; ++i) t[j > 2 ? pair(j, 2) : pair(2, j)][i] += ddy * double(sums[pair(j, 0)][i]);
            for (int i = 0; i < kLanes; ++i) t[pair(2, 2)][i] += ddy * ddy * double(sums[pair(0, 0)][i]);
            for (int c = 0; c < 3; ++c)
                for (int i = 0; i < kLanes; ++i) t[kPairs + 3 * 2 + c][i] += ddy * double(sums[kPairs + c][i]);
        }
    }
    // Each centre's solve, a vector of centres at a time (least_squares_lanes.hpp: the scalar
    // solve's bits). Lanes past the tile's width have all sums 0, so their fit is 0.
    using VD = DoubleVector<Isa>;
    constexpr int D = int(sizeof(VD) / sizeof(double));
    const double precision = (2 * r + 3) * double(FLT_EPSILON);
    const std::size_t beta_stride = std::size_t(3 * Terms) * kLanes;  // one bandwidth's fits
    for (int band = 0; band < B; ++band)
        for (int lane = 0; lane < width; lane += D) {
            VD a[Terms][Terms], b[Terms][3], beta[Terms][3];
            for (int j = 0; j < Terms; ++j) {
                for (int k = 0; k <= j; ++k) a[j][k] = load_doubles<VD>(total[band][pair(j, k)] + lane);
                for (int c = 0; c < 3; ++c) b[j][c] = load_doubles<VD>(total[band][kPairs + 3 * j + c] + lane);
            }
            solve_normal_equations_lanes<Terms>(a, b, beta, precision);
            float* fit = work.beta.data() + std::size_t(band) * beta_stride;
            for (int t = 0; t < Terms; ++t)
                for (int c = 0; c < 3; ++c)
                    for (int l = 0; l < D; ++l) fit[std::size_t(3 * t + c) * kLanes + std::size_t(lane + l)] = float(beta[t][c][l]);
        }
    // The predictions: every window pixel gets its centre's fit, weighted. The lanes whose window
    // pixel is outside the image, or past the tile's width, have weight 0 and land in the
    // buffer's padding or add 0. (Every bandwidth's buffer covers the same rows.)
    for (int dy = -r; dy <= r; ++dy) {
        const int y = cy + dy;
        if (y < res[0]->area.y0 || y >= res[0]->area.y1) continue;
        const WindowRow row = window_row_of(work, features, cy, dy);
        for (int b = 0; b < B; ++b) {
            float* const sum[4] = {res[b]->row(0, y), res[b]->row(1, y), res[b]->row(2, y), res[b]->row(3, y)};
            predict_row<Terms, V>(row, row.weight + std::size_t(b) * row.band_stride, work.beta.data() + std::size_t(b) * beta_stride,
                                  work.products.data(), sum);
        }
    }
}

// The loops, inlined into one function per instruction set (filter_isa.hpp).
template <int Terms, int B>
void fit_row_baseline(TileWork& work, int cy, TileResult* const* res) {
    fit_row<Terms, FilterIsa::Baseline, B>(work, cy, res);
}

template <int Terms, int B>
[[gnu::target("avx2")]] void fit_row_avx2(TileWork& work, int cy, TileResult* const* res) {
    fit_row<Terms, FilterIsa::Avx2, B>(work, cy, res);
}

template <int Terms, int B>
[[gnu::target("avx512f")]] void fit_row_avx512(TileWork& work, int cy, TileResult* const* res) {
    fit_row<Terms, FilterIsa::Avx512, B>(work, cy, res);
}

using FitRowFn = void (*)(TileWork&, int, TileResult* const*);

// Bandwidths fitted at once by one call: two (the first pass's candidates) share each window row's
// loads of terms and colours.
inline constexpr int kMaxBandsAtOnce = 2;

template <int B, int... T>
constexpr std::array<FitRowFn, sizeof...(T)> fit_table(std::integer_sequence<int, T...>, FilterIsa isa) {
    if (isa == FilterIsa::Avx512) return {&fit_row_avx512<T + 3, B>...};
    if (isa == FilterIsa::Avx2) return {&fit_row_avx2<T + 3, B>...};
    return {&fit_row_baseline<T + 3, B>...};
}

// fit_row for every number of terms from 3 (the offset terms alone) up, at index terms - 3, for
// one bandwidth ([0]) and two ([1]).
template <int B>
constexpr auto fits_of(FilterIsa isa) {
    return fit_table<B>(std::make_integer_sequence<int, kMaxRegressionTerms - 2>(), isa);
}
constexpr std::array<decltype(fits_of<1>(FilterIsa::Baseline)), kMaxBandsAtOnce> kFitsBaseline{fits_of<1>(FilterIsa::Baseline),
                                                                                                fits_of<2>(FilterIsa::Baseline)};
constexpr std::array<decltype(fits_of<1>(FilterIsa::Avx2)), kMaxBandsAtOnce> kFitsAvx2{fits_of<1>(FilterIsa::Avx2), fits_of<2>(FilterIsa::Avx2)};
constexpr std::array<decltype(fits_of<1>(FilterIsa::Avx512)), kMaxBandsAtOnce> kFitsAvx512{fits_of<1>(FilterIsa::Avx512),
                                                                                            fits_of<2>(FilterIsa::Avx512)};

// The weights exp(-d / k^2) of n distances.
[[gnu::always_inline]] inline void weights_of(const float* distance, std::size_t n, float scale, float* weight) {
    for (std::size_t i = 0; i < n; ++i) weight[i] = exp_weight(distance[i] * scale);
}

void weights_baseline(const float* distance, std::size_t n, float scale, float* weight) { weights_of(distance, n, scale, weight); }

[[gnu::target("avx2")]] void weights_avx2(const float* distance, std::size_t n, float scale, float* weight) {
    weights_of(distance, n, scale, weight);
}

[[gnu::target("avx512f")]] void weights_avx512(const float* distance, std::size_t n, float scale, float* weight) {
    weights_of(distance, n, scale, weight);
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
    // Each thread's working buffers, reused from tile to tile (each tile overwrites what it reads).
    struct Buffers {
        TileWork work;
        AlignedFloats distance;
        PatchScratch scratch;
    };
    tbb::enumerable_thread_specific<Buffers> thread_buffers;
    for_each_tile(tiles, [&](std::size_t index, const Rect& tile) {
        Buffers& buffers = thread_buffers.local();
        TileWork& work = buffers.work;
        AlignedFloats& distance = buffers.distance;
        work.tile = tile;
        work.r = r;
        work.stride = kLanes + 2 * r;
        // distance[row][offset][lane]: the largest channel distance decides (a window pixel must
        // resemble the centre in every channel); infinite where the window pixel is outside the
        // image, or the lane or row outside the tile (weight 0). A row of centres' distances are
        // contiguous, so its weights are taken into a buffer of 46 KB that stays in the core's L1
        // while the row's windows read it: laid out [offset][row][lane], a window row's 19 offsets
        // were 4 KB apart, so they fell in the same L1 set, more of them than its ways, and every
        // reload missed.
        const std::size_t offsets = std::size_t(side) * std::size_t(side), row_stride = offsets * kLanes;
        constexpr float kFar = std::numeric_limits<float>::infinity();
        distance.resize(std::size_t(kTileSize) * row_stride);
        for (int dy = -r, o = 0; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx, ++o) {
                float* const at = distance.data() + std::size_t(o) * kLanes;  // row 0 of offset o
                const Rect out = largest_patch_distances(guide, guide_variance, distance_params, tile, dx, dy, buffers.scratch, at, row_stride, isa);
                for (int y = tile.y0; y < tile.y0 + kTileSize; ++y) {
                    float* to = at + std::size_t(y - tile.y0) * row_stride;
                    if (out.empty() || y < out.y0 || y >= out.y1) {
                        std::fill(to, to + kLanes, kFar);
                        continue;
                    }
                    std::fill(to, to + (out.x0 - tile.x0), kFar);
                    std::fill(to + (out.x1 - tile.x0), to + kLanes, kFar);
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
        work.weight.resize(kMaxBandsAtOnce * row_stride);
        work.band_stride = row_stride;
        work.terms.resize(std::size_t(features.channels) * std::size_t(side) * kLanes);
        work.products.assign(4 * std::size_t(side) * std::size_t(kLanes + 4 * r), 0.0f);
        work.beta.assign(kMaxBandsAtOnce * std::size_t(3 * terms) * kLanes, 0.0f);
        const auto weights = isa == FilterIsa::Avx512 ? weights_avx512 : isa == FilterIsa::Avx2 ? weights_avx2 : weights_baseline;
        const auto& fits = isa == FilterIsa::Avx512 ? kFitsAvx512 : isa == FilterIsa::Avx2 ? kFitsAvx2 : kFitsBaseline;
        for (std::size_t b0 = 0; b0 < bandwidths.size(); b0 += kMaxBandsAtOnce) {
            const int bands = int(std::min<std::size_t>(kMaxBandsAtOnce, bandwidths.size() - b0));
            TileResult* res[kMaxBandsAtOnce] = {};
            float scale[kMaxBandsAtOnce] = {};
            for (int b = 0; b < bands; ++b) {
                scale[b] = 1.0f / (bandwidths[b0 + b] * bandwidths[b0 + b]);
                res[b] = &results[b0 + b][index];
                res[b]->area = {tile.x0 - r, std::max(tile.y0 - r, 0), tile.x0 + kLanes + r, std::min(tile.y1 + r, h)};
                res[b]->stride = res[b]->area.width();
                const std::size_t buffer = std::size_t(res[b]->stride) * std::size_t(res[b]->area.height());
                res[b]->sum.assign(3 * buffer, 0.0f);
                res[b]->weights.assign(buffer, 0.0f);
            }
            const FitRowFn fit = fits[std::size_t(bands - 1)][std::size_t(terms - 3)];
            for (int cy = tile.y0; cy < tile.y1; ++cy) {
                for (int b = 0; b < bands; ++b)
                    weights(distance.data() + std::size_t(cy - tile.y0) * row_stride, row_stride, scale[b], work.weight.data() + std::size_t(b) * row_stride);
                fit(work, cy, res);
            }
        }
    });
    // The tiles' buffers added into the image in tile order, in parallel over bands of rows: a band
    // adds the tiles over it in that order, so every pixel's sum is the same at any thread count.
    std::vector<Planes> out;
    for (const std::vector<TileResult>& tile_results : results) {
        Planes sum(w, h, 3);
        std::vector<float> weights(std::size_t(w) * std::size_t(h), 0.0f);
        for_each_chunk(std::size_t(h), kTileSize, [&](std::size_t band0, std::size_t band1) {
            for (const TileResult& res : tile_results) {
                // The buffer's columns inside the image (the rest is padding of weight 0).
                const std::size_t area_n = res.weights.size();
                for (int y = std::max(res.area.y0, int(band0)); y < std::min(res.area.y1, int(band1)); ++y)
                    for (int x = std::max(res.area.x0, 0); x < std::min(res.area.x1, w); ++x) {
                        const std::size_t q = std::size_t(y - res.area.y0) * std::size_t(res.stride) + std::size_t(x - res.area.x0);
                        const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
                        for (int c = 0; c < 3; ++c) sum.channel(c)[p] += res.sum[std::size_t(c) * area_n + q];
                        weights[p] += res.weights[q];
                    }
            }
            // Every pixel is its own window's centre with weight 1 (distance <= 0 to itself).
            const std::size_t p0 = band0 * std::size_t(w), p1 = band1 * std::size_t(w);
            for (int c = 0; c < 3; ++c)
                for (std::size_t p = p0; p < p1; ++p) sum.channel(c)[p] /= weights[p];
        });
        out.push_back(std::move(sum));
    }
    return out;
}

}  // namespace sweeptrace::denoise

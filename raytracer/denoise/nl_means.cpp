// NL-means over tiles (nl_means.hpp). For one offset (dx, dy) the distance of every pixel pair is
// computed once over the tile grown by the patch radius, then summed over the patch by a row pass
// and a column pass: 2 (2F + 1) additions per pixel instead of (2F + 1)^2, each sum taken afresh
// (no running sum, so no rounding carried from one pixel to the next) in registers, over a buffer
// padded with zeros, so every loop runs over a row of pixels without a branch and vectorizes.
#include "raytracer/denoise/nl_means.hpp"

#include <algorithm>
#include <cmath>

#include "raytracer/denoise/exp_weight.hpp"
#include "raytracer/denoise/float_vector.hpp"
#include "raytracer/denoise/tiles.hpp"

namespace sweeptrace::denoise {
namespace {

// A per-pixel distance is capped so that sums over a patch stay finite (a zero variance makes a
// difference infinitely far). Any value past exp_weight's underflow (87) gives weight 0; the cap
// keeps that true for the mean of the largest patch that holds one capped pixel (7x7: 1e4 / 49 =
// 204), and is far below float overflow when 49 capped pixels are summed.
constexpr float kDistanceCap = 1e4f;

[[gnu::always_inline]] inline float pixel_distance(float up, float uq, float vp, float vq, float k2) {
    const float diff = up - uq;
    const float num = diff * diff - (vp + std::min(vp, vq));
    const float den = k2 * (vp + vq);
    // No noise at either pixel: equal values are the same value, different ones are not. (The
    // quotient is computed either way and then chosen, so the loop has no branch to vectorize.)
    const float q = num / den;
    return den > 0.0f ? std::min(q, kDistanceCap) : num > 0.0f ? kDistanceCap : 0.0f;
}

// pixel_distance for a vector of pixels: the same operations lane by lane (std::min(a, b) is
// b < a ? b : a), so each lane's bits are the scalar's.
template <class V>
[[gnu::always_inline]] inline V pixel_distances(V up, V uq, V vp, V vq, V k2) {
    const V zero = broadcast<V>(0.0f), cap = broadcast<V>(kDistanceCap);
    const V diff = up - uq;
    const V num = diff * diff - (vp + (vq < vp ? vq : vp));
    const V den = k2 * (vp + vq);
    const V q = num / den;
    return den > zero ? (cap < q ? cap : q) : (num > zero ? cap : zero);
}

// The float vector of half V's width (a typedef with the attribute, as float_vector.hpp's: an
// attribute on a typedef used directly as a template argument is dropped).
template <class V>
struct HalfVectorOf {
    typedef float type __attribute__((vector_size(sizeof(V) / 2)));
};

// d[i] = pixel_distance(up[i], uq[i], s vp[i], s vq[i], k2) for i < n. The last vector overlaps
// the one before it rather than leaving the rest to a scalar loop: a grown tile's rows are 38,
// 66 or 70 pixels, and GCC's scalar remainder (a branch per pixel around its division) took as
// long as the vectors before it; the overlapped pixels are computed again to the same values.
template <class V>
[[gnu::always_inline]] inline void pixel_distance_row(const float* up, const float* uq, const float* vp, const float* vq, float s, float k2,
                                                      float* d, int n) {
    constexpr int L = kVectorLanes<V>;
    if (n < L) {
        for (int i = 0; i < n; ++i) d[i] = pixel_distance(up[i], uq[i], s * vp[i], s * vq[i], k2);
        return;
    }
    const V sv = broadcast<V>(s), k2v = broadcast<V>(k2);
    int i = 0;
    for (; i + L <= n; i += L)
        store_floats(d + i, pixel_distances(load_floats<V>(up + i), load_floats<V>(uq + i), sv * load_floats<V>(vp + i),
                                            sv * load_floats<V>(vq + i), k2v));
    if (i == n) return;
    // A rest of at most half a vector (the grown rows of 38, 66 and 70 pixels with AVX-512) in a
    // half-width vector: its division costs half of a full one.
    if constexpr (L >= 8) {
        using H = typename HalfVectorOf<V>::type;
        constexpr int M = L / 2;
        if (n - i <= M) {
            i = n - M;
            const H shv = broadcast<H>(s), k2h = broadcast<H>(k2);
            store_floats(d + i, pixel_distances(load_floats<H>(up + i), load_floats<H>(uq + i), shv * load_floats<H>(vp + i),
                                                shv * load_floats<H>(vq + i), k2h));
            return;
        }
    }
    i = n - L;
    store_floats(d + i, pixel_distances(load_floats<V>(up + i), load_floats<V>(uq + i), sv * load_floats<V>(vp + i),
                                        sv * load_floats<V>(vq + i), k2v));
}

[[gnu::always_inline]] inline Rect intersect(const Rect& a, const Rect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// dst[i] = src[i] + src[i + step] + ... + src[i + (n - 1) step] for i < count, summed in that
// order in registers. Four (or two) vectors of i at a time: each vector's sum is a chain of n - 1 dependent
// adds, and one chain at a time ran at the adds' latency (the row and column passes were a third
// of the distances' time on this machine's Intel core); four chains side by side keep the adder
// busy. The rest one vector at a time, the last one overlapping the one before (its sums taken
// again to the same values), and below a vector's width one at a time: the same operations.
template <class V>
[[gnu::always_inline]] inline void strided_sums(const float* src, std::size_t step, int n, float* dst, int count) {
    constexpr int L = kVectorLanes<V>;
    if (count < L) {
        for (int i = 0; i < count; ++i) {
            float sum = src[i];
            for (int t = 1; t < n; ++t) sum += src[std::size_t(t) * step + std::size_t(i)];
            dst[i] = sum;
        }
        return;
    }
    int i = 0;
    for (; i + 4 * L <= count; i += 4 * L) {
        V s0 = load_floats<V>(src + i), s1 = load_floats<V>(src + i + L), s2 = load_floats<V>(src + i + 2 * L),
          s3 = load_floats<V>(src + i + 3 * L);
        for (int t = 1; t < n; ++t) {
            const float* p = src + std::size_t(t) * step + std::size_t(i);
            s0 += load_floats<V>(p);
            s1 += load_floats<V>(p + L);
            s2 += load_floats<V>(p + 2 * L);
            s3 += load_floats<V>(p + 3 * L);
        }
        store_floats(dst + i, s0);
        store_floats(dst + i + L, s1);
        store_floats(dst + i + 2 * L, s2);
        store_floats(dst + i + 3 * L, s3);
    }
    if (i + 2 * L <= count) {  // the regression's 32-pixel rows
        V s0 = load_floats<V>(src + i), s1 = load_floats<V>(src + i + L);
        for (int t = 1; t < n; ++t) {
            const float* p = src + std::size_t(t) * step + std::size_t(i);
            s0 += load_floats<V>(p);
            s1 += load_floats<V>(p + L);
        }
        store_floats(dst + i, s0);
        store_floats(dst + i + L, s1);
        i += 2 * L;
    }
    while (i < count) {
        if (i + L > count) i = count - L;
        V sum = load_floats<V>(src + i);
        for (int t = 1; t < n; ++t) sum += load_floats<V>(src + std::size_t(t) * step + std::size_t(i));
        store_floats(dst + i, sum);
        i += L;
    }
}

// The loops, inlined into one function per instruction set (filter_isa.hpp) at the end of this
// namespace. Each channel's patch distances of `tile` to dist[c * tile pixels + (y - tile.y0) *
// tile.width() + (x - tile.x0)] or, Largest, only the largest of them to to[(y - tile.y0) *
// row_stride + (x - tile.x0)] (largest_patch_distances).
template <FilterIsa Isa, bool Largest = false>
[[gnu::always_inline]] inline Rect distances(const Planes& guide, const Planes& variance, const NlMeansParams& params, const Rect& tile,
                                             int dx, int dy, PatchScratch& scratch, std::vector<float>& dist, float* to = nullptr,
                                             std::size_t row_stride = 0) {
    const int w = guide.width, h = guide.height, f = params.patch_radius;
    const std::size_t tile_pixels = std::size_t(tile.width()) * std::size_t(tile.height());
    if constexpr (!Largest) dist.resize(std::size_t(guide.channels) * tile_pixels);
    // Pixels p with p and p + (dx, dy) both inside the image; patches are clipped to it too.
    const Rect valid{std::max(0, -dx), std::max(0, -dy), std::min(w, w - dx), std::min(h, h - dy)};
    const Rect out = intersect(tile, valid);
    if (out.empty()) return out;
    // The pixel distances over `out` grown by F, zero outside `valid` (a clipped patch's missing
    // pixels add nothing; the mean divides by the pixels it has).
    const Rect grown{out.x0 - f, out.y0 - f, out.x1 + f, out.y1 + f};
    const Rect pad = intersect(grown, valid);
    const int gw = grown.width(), gh = grown.height(), ow = out.width();
    // Only the part outside `pad` is zeroed: the rest is written for every channel below.
    scratch.pixel.resize(std::size_t(gw) * std::size_t(gh));
    for (int y = grown.y0; y < grown.y1; ++y) {
        float* d = scratch.pixel.data() + std::size_t(y - grown.y0) * std::size_t(gw);
        if (y < pad.y0 || y >= pad.y1) {
            std::fill(d, d + gw, 0.0f);
        } else {
            std::fill(d, d + (pad.x0 - grown.x0), 0.0f);
            std::fill(d + (pad.x1 - grown.x0), d + gw, 0.0f);
        }
    }
    scratch.row.resize(std::size_t(ow) * std::size_t(gh));
    scratch.column.resize(std::size_t(ow));
    scratch.count.resize(std::size_t(ow));
    if constexpr (Largest) scratch.largest.resize(std::size_t(ow) * std::size_t(out.height()));
    for (int x = out.x0; x < out.x1; ++x) scratch.count[std::size_t(x - out.x0)] = float(std::min(x + f + 1, pad.x1) - std::max(x - f, pad.x0));
    const float k2 = params.k * params.k, s = params.variance_scale;
    for (int c = 0; c < guide.channels; ++c) {
        const float* u = guide.channel(c);
        const float* v = variance.channel(c);
        for (int y = pad.y0; y < pad.y1; ++y) {
            const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(pad.x0), q = p + std::size_t(dy * w + dx);
            const float *up = u + p, *uq = u + q, *vp = v + p, *vq = v + q;
            float* d = scratch.pixel.data() + std::size_t(y - grown.y0) * std::size_t(gw) + std::size_t(pad.x0 - grown.x0);
            pixel_distance_row<FloatVector<Isa>>(up, uq, vp, vq, s, k2, d, pad.width());
        }
        // Along rows: the 2F + 1 pixels around each of out's columns.
        for (int y = 0; y < gh; ++y)
            strided_sums<FloatVector<Isa>>(scratch.pixel.data() + std::size_t(y) * std::size_t(gw), 1, 2 * f + 1,
                                           scratch.row.data() + std::size_t(y) * std::size_t(ow), ow);
        // Down columns, then the patch's mean distance (Largest: the largest sum so far, and
        // after the last channel its mean).
        if constexpr (Largest) {
            const bool last = c + 1 == guide.channels;
            for (int y = out.y0; y < out.y1; ++y) {
                const float* r = scratch.row.data() + std::size_t(y - out.y0) * std::size_t(ow);  // grown row y - F
                float* largest = scratch.largest.data() + std::size_t(y - out.y0) * std::size_t(ow);
                if (c == 0) {
                    strided_sums<FloatVector<Isa>>(r, std::size_t(ow), 2 * f + 1, largest, ow);
                } else {
                    float* column = scratch.column.data();
                    strided_sums<FloatVector<Isa>>(r, std::size_t(ow), 2 * f + 1, column, ow);
                    for (int i = 0; i < ow; ++i) largest[i] = std::max(largest[i], column[i]);
                }
                if (last) {
                    const float rows = float(std::min(y + f + 1, pad.y1) - std::max(y - f, pad.y0));
                    float* line = to + std::size_t(y - tile.y0) * row_stride + std::size_t(out.x0 - tile.x0);
                    for (int i = 0; i < ow; ++i) line[i] = largest[i] / (rows * scratch.count[std::size_t(i)]);
                }
            }
            continue;
        }
        float* o = dist.data() + std::size_t(c) * tile_pixels;
        float* column = scratch.column.data();
        for (int y = out.y0; y < out.y1; ++y) {
            const float* r = scratch.row.data() + std::size_t(y - out.y0) * std::size_t(ow);  // grown row y - F
            strided_sums<FloatVector<Isa>>(r, std::size_t(ow), 2 * f + 1, column, ow);
            const float rows = float(std::min(y + f + 1, pad.y1) - std::max(y - f, pad.y0));
            float* line = o + std::size_t(y - tile.y0) * std::size_t(tile.width()) + std::size_t(out.x0 - tile.x0);
            for (int i = 0; i < ow; ++i) line[i] = column[i] / (rows * scratch.count[std::size_t(i)]);
        }
    }
    return out;
}

// One tile of nl_means: `result`'s pixels of `tile`.
template <FilterIsa Isa>
[[gnu::always_inline]] inline void filter_tile(const Planes& image, const Planes& guide, const Planes& variance, const NlMeansParams& params,
                                               const Rect& tile, Planes& result) {
    // Image channel c is weighted by guide channel c mod (the guide's channels): one set of
    // weights serves every image filtered with the same guide.
    const int w = image.width, channels = image.channels, guides = guide.channels, r = params.search_radius;
    const std::size_t n = std::size_t(tile.width()) * std::size_t(tile.height()), tw = std::size_t(tile.width());
    std::vector<float> sum(std::size_t(channels) * n, 0.0f), weight_sum(std::size_t(guides) * n, 0.0f), weight(tw);
    std::vector<float> dist;
    PatchScratch scratch;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const Rect out = distances<Isa>(guide, variance, params, tile, dx, dy, scratch, dist);
            for (int g = 0; g < guides; ++g)
                for (int y = out.y0; y < out.y1; ++y) {
                    const std::size_t row = std::size_t(y - tile.y0) * tw + std::size_t(out.x0 - tile.x0);
                    const float* d = dist.data() + std::size_t(g) * n + row;
                    float* ws = weight_sum.data() + std::size_t(g) * n + row;
                    const std::size_t q_row = std::size_t(y + dy) * std::size_t(w) + std::size_t(out.x0 + dx);
                    // One or two image channels per guide (the prefilter and the selection; the
                    // two error maps): the weight used where it is computed, not stored and read
                    // back. The same sums in the same order.
                    if (channels == guides) {
                        const float* q = image.channel(g) + q_row;
                        float* s = sum.data() + std::size_t(g) * n + row;
                        for (int i = 0; i < out.width(); ++i) {
                            const float wt = exp_weight(d[i]);
                            ws[i] += wt;
                            s[i] += wt * q[i];
                        }
                        continue;
                    }
                    if (channels == 2 * guides) {
                        const float* q0 = image.channel(g) + q_row;
                        const float* q1 = image.channel(g + guides) + q_row;
                        float* s0 = sum.data() + std::size_t(g) * n + row;
                        float* s1 = sum.data() + std::size_t(g + guides) * n + row;
                        for (int i = 0; i < out.width(); ++i) {
                            const float wt = exp_weight(d[i]);
                            ws[i] += wt;
                            s0[i] += wt * q0[i];
                            s1[i] += wt * q1[i];
                        }
                        continue;
                    }
                    for (int i = 0; i < out.width(); ++i) {
                        weight[std::size_t(i)] = exp_weight(d[i]);
                        ws[i] += weight[std::size_t(i)];
                    }
                    for (int c = g; c < channels; c += guides) {
                        const float* q = image.channel(c) + std::size_t(y + dy) * std::size_t(w) + std::size_t(out.x0 + dx);
                        float* s = sum.data() + std::size_t(c) * n + row;
                        for (int i = 0; i < out.width(); ++i) s[i] += weight[std::size_t(i)] * q[i];
                    }
                }
        }
    // The pixel itself has distance <= 0 (weight 1), so every sum of weights is at least 1.
    for (int c = 0; c < channels; ++c)
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                const std::size_t i = std::size_t(y - tile.y0) * tw + std::size_t(x - tile.x0);
                result.at(c, x, y) = sum[std::size_t(c) * n + i] / weight_sum[std::size_t(c % guides) * n + i];
            }
}

Rect largest_baseline(const Planes& guide, const Planes& variance, const NlMeansParams& params, const Rect& tile, int dx, int dy,
                      PatchScratch& scratch, float* to, std::size_t row_stride) {
    std::vector<float> unused;
    return distances<FilterIsa::Baseline, true>(guide, variance, params, tile, dx, dy, scratch, unused, to, row_stride);
}

[[gnu::target("avx2")]] Rect largest_avx2(const Planes& guide, const Planes& variance, const NlMeansParams& params, const Rect& tile,
                                          int dx, int dy, PatchScratch& scratch, float* to, std::size_t row_stride) {
    std::vector<float> unused;
    return distances<FilterIsa::Avx2, true>(guide, variance, params, tile, dx, dy, scratch, unused, to, row_stride);
}

[[gnu::target("avx512f")]] Rect largest_avx512(const Planes& guide, const Planes& variance, const NlMeansParams& params, const Rect& tile,
                                             int dx, int dy, PatchScratch& scratch, float* to, std::size_t row_stride) {
    std::vector<float> unused;
    return distances<FilterIsa::Avx512, true>(guide, variance, params, tile, dx, dy, scratch, unused, to, row_stride);
}

void filter_tile_baseline(const Planes& image, const Planes& guide, const Planes& variance, const NlMeansParams& params, const Rect& tile,
                          Planes& result) {
    filter_tile<FilterIsa::Baseline>(image, guide, variance, params, tile, result);
}

[[gnu::target("avx2")]] void filter_tile_avx2(const Planes& image, const Planes& guide, const Planes& variance, const NlMeansParams& params,
                                              const Rect& tile, Planes& result) {
    filter_tile<FilterIsa::Avx2>(image, guide, variance, params, tile, result);
}

[[gnu::target("avx512f")]] void filter_tile_avx512(const Planes& image, const Planes& guide, const Planes& variance, const NlMeansParams& params,
                                                const Rect& tile, Planes& result) {
    filter_tile<FilterIsa::Avx512>(image, guide, variance, params, tile, result);
}

}  // namespace

Rect largest_patch_distances(const Planes& guide, const Planes& variance, const NlMeansParams& params, const Rect& tile, int dx, int dy,
                             PatchScratch& scratch, float* to, std::size_t row_stride, FilterIsa isa) {
    const auto largest_of = isa == FilterIsa::Avx512 ? largest_avx512 : isa == FilterIsa::Avx2 ? largest_avx2 : largest_baseline;
    return largest_of(guide, variance, params, tile, dx, dy, scratch, to, row_stride);
}

Planes nl_means(const Planes& image, const Planes& guide, const Planes& variance, const NlMeansParams& params, FilterIsa isa) {
    Planes result(image.width, image.height, image.channels);
    const auto filter = isa == FilterIsa::Avx512 ? filter_tile_avx512 : isa == FilterIsa::Avx2 ? filter_tile_avx2 : filter_tile_baseline;
    for_each_tile(image_tiles(image.width, image.height, kNlMeansTileSize),
                  [&](std::size_t, const Rect& tile) { filter(image, guide, variance, params, tile, result); });
    return result;
}

}  // namespace sweeptrace::denoise

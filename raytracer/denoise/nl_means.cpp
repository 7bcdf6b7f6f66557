// NL-means over tiles (nl_means.hpp). For one offset (dx, dy) the distance of every pixel pair is
// computed once over the tile grown by the patch radius, then summed over the patch by two 1-D
// running sums: four additions per pixel instead of (2F + 1)^2.
#include "raytracer/denoise/nl_means.hpp"

#include <algorithm>
#include <cmath>

#include "raytracer/denoise/tiles.hpp"

namespace sweeptrace::denoise {
namespace {

// A per-pixel distance is capped so that sums over a patch stay finite (a zero variance makes a
// difference infinitely far). Any value past exp's float underflow (~104) gives weight 0; the
// cap keeps that true for the mean of the largest patch that holds one capped pixel (7x7: 1e4 / 49
// = 204), and is far below float overflow when 49 capped pixels are summed.
constexpr float kDistanceCap = 1e4f;

float pixel_distance(float up, float uq, float vp, float vq, float k2) {
    const float diff = up - uq;
    const float num = diff * diff - (vp + std::min(vp, vq));
    const float den = k2 * (vp + vq);
    // No noise at either pixel: equal values are the same value, different ones are not. (The
    // quotient is computed either way and then chosen, so the loop has no branch to vectorize.)
    const float q = num / den;
    return den > 0.0f ? std::min(q, kDistanceCap) : num > 0.0f ? kDistanceCap : 0.0f;
}

Rect intersect(const Rect& a, const Rect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

}  // namespace

Rect patch_distances(const Planes& guide, const Planes& variance, const NlMeansParams& params, const Rect& tile, int dx, int dy,
                     PatchScratch& scratch, std::vector<float>& dist) {
    const int w = guide.width, h = guide.height, f = params.patch_radius;
    const std::size_t tile_pixels = std::size_t(tile.width()) * std::size_t(tile.height());
    dist.resize(std::size_t(guide.channels) * tile_pixels);
    // Pixels p with p and p + (dx, dy) both inside the image; patches are clipped to it too.
    const Rect valid{std::max(0, -dx), std::max(0, -dy), std::min(w, w - dx), std::min(h, h - dy)};
    const Rect out = intersect(tile, valid);
    if (out.empty()) return out;
    const Rect pad = intersect({out.x0 - f, out.y0 - f, out.x1 + f, out.y1 + f}, valid);
    const int pw = pad.width(), ph = pad.height(), ow = out.width();
    scratch.pixel.resize(std::size_t(pw) * std::size_t(ph));
    scratch.row.resize(std::size_t(ow) * std::size_t(ph));
    scratch.column.resize(std::size_t(ow));
    scratch.patch_columns.resize(std::size_t(ow));
    for (int x = out.x0; x < out.x1; ++x)
        scratch.patch_columns[std::size_t(x - out.x0)] = double(std::min(x + f + 1, pad.x1) - std::max(x - f, pad.x0));
    const float k2 = params.k * params.k, s = params.variance_scale;
    for (int c = 0; c < guide.channels; ++c) {
        const float* u = guide.channel(c);
        const float* v = variance.channel(c);
        for (int y = pad.y0; y < pad.y1; ++y) {
            const std::size_t rp = std::size_t(y) * std::size_t(w), rq = std::size_t(y + dy) * std::size_t(w);
            float* d = scratch.pixel.data() + std::size_t(y - pad.y0) * std::size_t(pw);
            for (int x = pad.x0; x < pad.x1; ++x)
                d[x - pad.x0] = pixel_distance(u[rp + std::size_t(x)], u[rq + std::size_t(x + dx)], s * v[rp + std::size_t(x)],
                                               s * v[rq + std::size_t(x + dx)], k2);
        }
        // Along rows, then down columns: running sums over the patch (clipped to `pad`), in double
        // so that a capped distance leaving the window leaves no rounding behind worth a weight.
        for (int y = 0; y < ph; ++y) {
            const float* d = scratch.pixel.data() + std::size_t(y) * std::size_t(pw);
            float* r = scratch.row.data() + std::size_t(y) * std::size_t(ow);
            double sum = 0.0;
            int a = std::max(out.x0 - f, pad.x0), b = a;  // the window [a, b) in image columns
            for (int x = out.x0; x < out.x1; ++x) {
                for (; b < std::min(x + f + 1, pad.x1); ++b) sum += d[b - pad.x0];
                for (; a < x - f; ++a) sum -= d[a - pad.x0];
                r[x - out.x0] = float(sum);
            }
        }
        // Down columns, all columns at once (row by row, so the additions vectorize).
        float* o = dist.data() + std::size_t(c) * tile_pixels;
        std::fill(scratch.column.begin(), scratch.column.end(), 0.0);
        int a = std::max(out.y0 - f, pad.y0), b = a;  // the window [a, b) in image rows
        for (int y = out.y0; y < out.y1; ++y) {
            for (; b < std::min(y + f + 1, pad.y1); ++b) {
                const float* r = scratch.row.data() + std::size_t(b - pad.y0) * std::size_t(ow);
                for (int i = 0; i < ow; ++i) scratch.column[std::size_t(i)] += r[i];
            }
            for (; a < y - f; ++a) {
                const float* r = scratch.row.data() + std::size_t(a - pad.y0) * std::size_t(ow);
                for (int i = 0; i < ow; ++i) scratch.column[std::size_t(i)] -= r[i];
            }
            // the patch's mean distance
            float* line = o + std::size_t(y - tile.y0) * std::size_t(tile.width()) + std::size_t(out.x0 - tile.x0);
            for (int i = 0; i < ow; ++i) line[i] = float(scratch.column[std::size_t(i)] / (double(b - a) * scratch.patch_columns[std::size_t(i)]));
        }
    }
    return out;
}

Planes nl_means(const Planes& image, const Planes& guide, const Planes& variance, const NlMeansParams& params) {
    const int w = image.width, h = image.height, channels = image.channels, r = params.search_radius;
    Planes result(w, h, channels);
    const std::vector<Rect> tiles = image_tiles(w, h);
    for_each_tile(tiles, [&](std::size_t, const Rect& tile) {
        const std::size_t n = std::size_t(tile.width()) * std::size_t(tile.height());
        std::vector<double> sum(std::size_t(channels) * n, 0.0), weight_sum(std::size_t(channels) * n, 0.0);
        std::vector<float> dist;
        PatchScratch scratch;
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
                const Rect out = patch_distances(guide, variance, params, tile, dx, dy, scratch, dist);
                for (int c = 0; c < channels; ++c) {
                    const float* src = image.channel(c);
                    for (int y = out.y0; y < out.y1; ++y)
                        for (int x = out.x0; x < out.x1; ++x) {
                            const std::size_t i = std::size_t(c) * n + std::size_t(y - tile.y0) * std::size_t(tile.width()) + std::size_t(x - tile.x0);
                            const float weight = std::exp(-std::max(dist[i], 0.0f));
                            sum[i] += double(weight) * src[std::size_t(y + dy) * std::size_t(w) + std::size_t(x + dx)];
                            weight_sum[i] += weight;
                        }
                }
            }
        // The pixel itself has distance <= 0 (weight 1), so every sum of weights is at least 1.
        for (int c = 0; c < channels; ++c)
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x) {
                    const std::size_t i = std::size_t(c) * n + std::size_t(y - tile.y0) * std::size_t(tile.width()) + std::size_t(x - tile.x0);
                    result.at(c, x, y) = float(sum[i] / weight_sum[i]);
                }
    });
    return result;
}

}  // namespace sweeptrace::denoise

#include "raytracer/denoise/halves_variance.hpp"

#include <algorithm>
#include <vector>

#include "raytracer/denoise/tiles.hpp"

namespace sweeptrace::denoise {
namespace {

// Sums of `in` (one channel, width x height) over the clipped 2r + 1 pixels around every pixel
// along its row (dx = 1, dy = 0) or its column (dx = 0, dy = 1), each sum taken afresh (no running
// sum whose subtractions would leave rounding behind beside large values: a window of zeros sums
// to 0), into `out` (every element written). Rows in parallel, each sum alone: the same bits at
// any thread count.
void line_sums(const std::vector<double>& in, int width, int height, int r, int dx, int dy, std::vector<double>& out) {
    for_each_chunk(std::size_t(height), 8, [&](std::size_t y0, std::size_t y1) {
        for (int y = int(y0); y < int(y1); ++y)
            for (int x = 0; x < width; ++x) {
                // t runs over the pixels (x + t dx, y + t dy) inside the image
                const int lo = std::max(-r, dx ? -x : -y), hi = std::min(r, dx ? width - 1 - x : height - 1 - y);
                double sum = 0.0;
                for (int t = lo; t <= hi; ++t) sum += in[std::size_t(y + t * dy) * std::size_t(width) + std::size_t(x + t * dx)];
                out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = sum;
            }
    });
}

// The sums over the clipped (2r + 1)^2 window of every pixel, into `out`: along rows (into
// `rows`), then along columns. The buffers are the caller's, reused for every channel: allocated
// afresh, a whole image of doubles was zero-filled and page-faulted in four times per channel.
void window_sums(const std::vector<double>& values, int width, int height, int r, std::vector<double>& rows, std::vector<double>& out) {
    line_sums(values, width, height, r, 1, 0, rows);
    line_sums(rows, width, height, r, 0, 1, out);
}

}  // namespace

Planes halves_variance(const Buffers& buffers, int radius) {
    Planes out = buffers.variance;
    const std::size_t n = out.pixels();
    std::vector<double> spread(n), variance(n), rows(n), spread_sum(n), variance_sum(n);
    for (int c = 0; c < out.channels; ++c) {
        const float* even = buffers.even.channel(c);
        const float* odd = buffers.odd.channel(c);
        const float* var = buffers.variance.channel(c);
        for_each_chunk(n, 4096, [&](std::size_t i0, std::size_t i1) {
            for (std::size_t i = i0; i < i1; ++i) {
                const double d = double(even[i]) - double(odd[i]);
                spread[i] = 0.25 * d * d;
                variance[i] = var[i];
            }
        });
        window_sums(spread, out.width, out.height, radius, rows, spread_sum);
        window_sums(variance, out.width, out.height, radius, rows, variance_sum);
        float* dst = out.channel(c);
        for_each_chunk(n, 4096, [&](std::size_t i0, std::size_t i1) {
            for (std::size_t i = i0; i < i1; ++i)
                if (variance_sum[i] > 0.0) dst[i] = float(double(var[i]) * spread_sum[i] / variance_sum[i]);
        });
    }
    return out;
}

}  // namespace sweeptrace::denoise

#include "raytracer/denoise/halves_variance.hpp"

#include <algorithm>
#include <vector>

#include "raytracer/denoise/tiles.hpp"

namespace sweeptrace::denoise {
namespace {

// Sums of `in` (one channel, width x height) over the clipped 2r + 1 pixels around every pixel
// along its row or (columns) its column, each sum taken afresh (no running
// sum whose subtractions would leave rounding behind beside large values: a window of zeros sums
// to 0), into `out` (every element written). Rows in parallel, each sum alone: the same bits at
// any thread count. Each sum is 0 + in(first) + ... + in(last) in that order; where the window is
// the same for a run of pixels (every pixel of a row for the column sums, the pixels r or more
// from the ends for the row sums) the run's sums are taken side by side, one term of all of them
// at a time, so the loop vectorizes (one pixel's 19-term chain at a time ran at the adds' latency).
void line_sums(const std::vector<double>& in, int width, int height, int r, bool columns, std::vector<double>& out) {
    for_each_chunk(std::size_t(height), 8, [&](std::size_t y0, std::size_t y1) {
        for (int y = int(y0); y < int(y1); ++y) {
            double* o = out.data() + std::size_t(y) * std::size_t(width);
            if (columns) {
                const int lo = std::max(-r, -y), hi = std::min(r, height - 1 - y);
                const double* first = in.data() + std::size_t(y + lo) * std::size_t(width);
                for (int x = 0; x < width; ++x) o[x] = 0.0 + first[x];
                for (int t = lo + 1; t <= hi; ++t) {
                    const double* row = in.data() + std::size_t(y + t) * std::size_t(width);
                    for (int x = 0; x < width; ++x) o[x] += row[x];
                }
                continue;
            }
            const double* row = in.data() + std::size_t(y) * std::size_t(width);
            // x in [r, width - r): the whole window inside the row
            const int inner0 = std::min(r, width), inner1 = std::max(inner0, width - r);
            for (int x = inner0; x < inner1; ++x) o[x] = 0.0 + row[x - r];
            for (int t = -r + 1; t <= r; ++t)
                for (int x = inner0; x < inner1; ++x) o[x] += row[x + t];
            // The pixels nearer an end than r: their windows clipped, one at a time.
            const auto clipped = [&](int x) {
                const int lo = std::max(-r, -x), hi = std::min(r, width - 1 - x);
                double sum = 0.0;
                for (int t = lo; t <= hi; ++t) sum += row[x + t];
                o[x] = sum;
            };
            for (int x = 0; x < inner0; ++x) clipped(x);
            for (int x = inner1; x < width; ++x) clipped(x);
        }
    });
}

// The sums over the clipped (2r + 1)^2 window of every pixel, into `out`: along rows (into
// `rows`), then along columns. The buffers are the caller's, reused for every channel: allocated
// afresh, a whole image of doubles was zero-filled and page-faulted in four times per channel.
void window_sums(const std::vector<double>& values, int width, int height, int r, std::vector<double>& rows, std::vector<double>& out) {
    line_sums(values, width, height, r, false, rows);
    line_sums(rows, width, height, r, true, out);
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

// The variance NFOR works with (denoise/halves_variance.hpp): the renderer's sample variance
// brought to the scale the two halves show, pixel detail kept.
#include <catch2/catch.hpp>

#include <cmath>

#include "raytracer/denoise/halves_variance.hpp"

using namespace sweeptrace;
using namespace sweeptrace::denoise;

TEST_CASE("halves variance: the sample variance scaled to the halves' spread, 0 kept", "[denoise]") {
    const int w = 30, h = 20;
    Buffers b{{w, h, 2}, {w, h, 2}, {w, h, 2}, {w, h, 2}};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Channel 0: a variance that grows across the image; halves whose (even - odd)^2 / 4
            // is exactly a third of it (stratified halves, as sobol-halves gives).
            const float v = 1e-3f * float(1 + x + y);
            const float d = std::sqrt(4.0f * v / 3.0f) * ((x + y) % 2 ? 1.0f : -1.0f);
            b.variance.at(0, x, y) = v;
            b.even.at(0, x, y) = 0.5f + 0.5f * d;
            b.odd.at(0, x, y) = 0.5f - 0.5f * d;
            // Channel 1: no variance on the left half (a flat textured wall), equal halves there.
            const bool noisy = x >= w / 2;
            b.variance.at(1, x, y) = noisy ? 0.01f : 0.0f;
            b.even.at(1, x, y) = noisy ? 0.4f : 0.3f;
            b.odd.at(1, x, y) = noisy ? 0.2f : 0.3f;
        }
    const Planes out = halves_variance(b, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            INFO("pixel " << x << ", " << y);
            // The ratio of the window's sums is a third wherever the window lies; per pixel, the
            // sample variance's own detail.
            CHECK(out.at(0, x, y) == Approx(b.variance.at(0, x, y) / 3.0f).epsilon(1e-5));
            if (x < w / 2) CHECK(out.at(1, x, y) == 0.0f);
            // (0.4 - 0.2)^2 / 4 = 0.01: halves as far apart as the variance says, unchanged
            // where the window holds only noisy pixels.
            if (x >= w / 2 + 3) CHECK(out.at(1, x, y) == Approx(0.01f).epsilon(1e-5));
        }
}

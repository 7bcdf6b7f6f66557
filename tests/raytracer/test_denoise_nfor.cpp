// NFOR (raytracer/denoise/) on synthetic images whose truth is known: a constant image comes back
// unchanged, a colour that depends linearly on a high-frequency feature is recovered (which no
// spatial filter of the noisy colour can do), any thread count gives the same bits, and the
// regression's solve survives the singular windows every flat wall gives it.
#include <catch2/catch.hpp>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include "denoise_test_images.hpp"
#include "raytracer/denoise/exp_weight.hpp"
#include "raytracer/denoise/least_squares.hpp"
#include "raytracer/denoise/least_squares_lanes.hpp"
#include "raytracer/denoise/nfor.hpp"
#include "raytracer/input_error.hpp"

namespace {

using namespace sweeptrace;
using namespace sweeptrace::testing;

double rmse(const denoise::Planes& a, const denoise::Planes& b) {
    double s = 0.0;
    for (std::size_t i = 0; i < a.data.size(); ++i) s += double(a.data[i] - b.data[i]) * double(a.data[i] - b.data[i]);
    return std::sqrt(s / double(a.data.size()));
}

denoise::Planes run_nfor(const denoise::NforInput& in, int threads, denoise::FilterIsa isa = denoise::FilterIsa::Baseline) {
    tbb::task_arena arena(threads);
    denoise::Planes out;
    arena.execute([&] { out = denoise::nfor(in, isa); });
    return out;
}

// A box filter of the noisy mean, radius r: the "blur of the same strength" NFOR must beat.
denoise::Planes box_blur(const denoise::Planes& img, int r) {
    denoise::Planes out(img.width, img.height, img.channels);
    for (int c = 0; c < img.channels; ++c)
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                double s = 0.0;
                int n = 0;
                for (int dy = -r; dy <= r; ++dy)
                    for (int dx = -r; dx <= r; ++dx)
                        if (x + dx >= 0 && x + dx < img.width && y + dy >= 0 && y + dy < img.height) {
                            s += img.at(c, x + dx, y + dy);
                            ++n;
                        }
                out.at(c, x, y) = float(s / n);
            }
    return out;
}

}  // namespace

TEST_CASE("nfor: a constant image comes back unchanged, whatever its noisy features", "[denoise]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float value[3] = {0.25f, 0.5f, 4.0f};
    SyntheticImage s = synthetic_image(
        40, 36, 3, 0.0f, [&](int, int, int) { return u(rng); }, [&](int, int, int c, const float*) { return value[c]; });
    // Noise is stated (variance of the mean 1e-2) though none was drawn, so the filters average.
    for (float& v : s.input.color.variance.data) v = 1e-2f;
    for (float& v : s.input.features.variance.data) v = 1e-2f;
    const denoise::Planes out = run_nfor(s.input, 2);
    REQUIRE(out.width == 40);
    REQUIRE(out.height == 36);
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x) worst = std::max(worst, std::abs(double(out.at(c, x, y)) / value[c] - 1.0));
    INFO("largest relative deviation " << worst);
    // float rounding of sums over a few hundred window pixels, not a filter's error
    CHECK(worst < 1e-5);
}

TEST_CASE("nfor: a colour linear in a per-pixel texture is recovered from its noise, which a box blur cannot do", "[denoise]") {
    const float sigma = 0.1f;  // one half's noise; the mean's is 0.071
    const SyntheticImage s = textured_image(48, 40, 11, sigma);
    const denoise::Planes out = run_nfor(s.input, 2);
    const double raw = rmse(s.input.color.mean, s.truth), denoised = rmse(out, s.truth);
    const double blurred = rmse(box_blur(s.input.color.mean, 2), s.truth);
    INFO("rmse raw " << raw << ", NFOR " << denoised << ", 5x5 box " << blurred);
    // The regression fits colour = a + b albedo in every window and the truth is exactly that:
    // what is left is the fit's noise, a small share of the raw noise.
    CHECK(denoised < 0.5 * raw);
    // The texture is per pixel: a spatial filter blurs it away and ends worse than the raw image.
    CHECK(blurred > raw);
}

TEST_CASE("nfor: the result is never negative, where the noisy input is", "[denoise]") {
    // A black image with noise about 0: half its noisy values are negative, and so would be about
    // half of any unbiased filter's output.
    const SyntheticImage s = synthetic_image(
        40, 30, 11, 0.05f, [](int, int, int f) { return f < 3 ? 0.5f : f < 6 ? (f == 5 ? 1.0f : 0.0f) : 2.0f; },
        [](int, int, int, const float*) { return 0.0f; });
    int negative_input = 0;
    for (float v : s.input.color.mean.data) negative_input += v < 0.0f;
    CHECK(negative_input > int(s.input.color.mean.data.size()) / 4);
    const denoise::Planes out = denoise::nfor(s.input, denoise::FilterIsa::Baseline);
    for (float v : out.data) REQUIRE(v >= 0.0f);
}

TEST_CASE("nfor: 1 and 2 threads give the same bits", "[denoise]") {
    const SyntheticImage s = textured_image(70, 40, 5, 0.2f);  // 3x2 tiles, one partial
    const denoise::Planes one = run_nfor(s.input, 1), two = run_nfor(s.input, 2);
    REQUIRE(one.data.size() == two.data.size());
    CHECK(std::memcmp(one.data.data(), two.data.data(), one.data.size() * sizeof(float)) == 0);
}

TEST_CASE("nfor: the AVX2 and AVX-512 loops give the baseline's bits", "[denoise]") {
    const SyntheticImage s = textured_image(70, 40, 5, 0.2f);  // 3x2 tiles, one partial
    const denoise::Planes baseline = run_nfor(s.input, 2, denoise::FilterIsa::Baseline);
    __builtin_cpu_init();
    struct Wide {
        denoise::FilterIsa isa;
        const char* name;
        bool supported;
    };
    for (const Wide& wide_isa : {Wide{denoise::FilterIsa::Avx2, "AVX2", __builtin_cpu_supports("avx2") != 0},
                                 Wide{denoise::FilterIsa::Avx512, "AVX-512", __builtin_cpu_supports("avx512f") != 0}}) {
        const auto [isa, name, supported] = wide_isa;
        if (!supported) {
            WARN("this CPU has no " << name << ": its loops do not run here");
            continue;
        }
        INFO(name);
        const denoise::Planes wide = run_nfor(s.input, 2, isa);
        REQUIRE(baseline.data.size() == wide.data.size());
        CHECK(std::memcmp(baseline.data.data(), wide.data.data(), baseline.data.size() * sizeof(float)) == 0);
    }
}

TEST_CASE("nfor: the window solve gives a constant feature coefficient 0 and still fits the rest", "[denoise]") {
    // colour = 2 + 3 t over t = 0..4, with a second column constant 0 (a flat wall's normal,
    // relative to the centre) and a third equal to the first (two features that say the same).
    const int n = 4;
    double a[n * n] = {}, b[n * 3] = {}, beta[n * 3];
    for (int t = 0; t < 5; ++t) {
        const double x[n] = {1.0, double(t), 0.0, double(t)};
        const double y = 2.0 + 3.0 * t;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) a[i * n + j] += x[i] * x[j];
            for (int c = 0; c < 3; ++c) b[i * 3 + c] += x[i] * y * (c + 1);
        }
    }
    denoise::solve_normal_equations(a, b, n, beta, DBL_EPSILON);
    for (int c = 0; c < 3; ++c) {
        CHECK(beta[0 * 3 + c] == Approx(2.0 * (c + 1)));
        CHECK(beta[2 * 3 + c] == 0.0);
        // The two equal columns share the slope; which one carries it is the pivot's choice.
        CHECK(beta[1 * 3 + c] + beta[3 * 3 + c] == Approx(3.0 * (c + 1)));
    }
}

TEST_CASE("nfor: the window solve a vector of windows at a time gives each window the scalar solve's bits", "[denoise]") {
    // 64 windows of 10 terms (NFOR's 3 + 7 features), 2 to a vector (the baseline ISA's; wider
    // vectors run the same lane operations, and the ISAs' NFOR bits are compared above): full
    // rank, with a column 0 (a flat wall's feature), with two equal columns (the pivot search
    // ties, at the first step or after others), with a column 1e-5 times another's plus a little
    // (stopped by the tolerance partway), of rank 1, and all zero (a lane past the tile's width).
    constexpr int n = 10, lanes = 2, windows = 64;
    typedef double Lanes __attribute__((vector_size(lanes * sizeof(double))));
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    std::vector<std::array<double, n * n>> as(windows);
    std::vector<std::array<double, n * 3>> bs(windows);
    for (int w = 0; w < windows; ++w) {
        const int kind = w % 6;
        as[w].fill(0.0);
        bs[w].fill(0.0);
        for (int row = 0; row < 40; ++row) {
            double x[n];
            for (double& v : x) v = normal(rng);
            x[0] = 1.0;
            if (kind == 1) x[4] = 0.0;
            if (kind == 2) x[7] = x[3];
            if (kind == 3) x[9] = 1e-5 * x[5] + 1e-9 * normal(rng);
            if (kind == 4)
                for (int i = 1; i < n; ++i) x[i] = 0.5 * i;
            if (kind == 5)
                for (double& v : x) v = 0.0;
            const double weight = std::exp(-std::abs(normal(rng)));
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j <= i; ++j) as[w][i * n + j] += weight * x[i] * x[j];
                for (int c = 0; c < 3; ++c) bs[w][i * 3 + c] += weight * x[i] * (c + 1.0 + normal(rng));
            }
        }
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < i; ++j) as[w][j * n + i] = as[w][i * n + j];  // symmetric, as the regression's
    }
    const double precision = 21 * double(FLT_EPSILON);  // the regression's
    int compared = 0;
    for (int v = 0; v < windows / lanes; ++v) {
        Lanes a[n][n], b[n][3], beta[n][3];
        for (int i = 0; i < n; ++i)
            for (int l = 0; l < lanes; ++l) {
                for (int j = 0; j <= i; ++j) a[i][j][l] = as[v * lanes + l][i * n + j];
                for (int c = 0; c < 3; ++c) b[i][c][l] = bs[v * lanes + l][i * 3 + c];
            }
        denoise::solve_normal_equations_lanes<n>(a, b, beta, precision);
        for (int l = 0; l < lanes; ++l) {
            std::array<double, n * n> a1 = as[v * lanes + l];
            std::array<double, n * 3> b1 = bs[v * lanes + l];
            double beta1[n * 3];
            denoise::solve_normal_equations(a1.data(), b1.data(), n, beta1, precision);
            for (int t = 0; t < n; ++t)
                for (int c = 0; c < 3; ++c) {
                    INFO("window " << v * lanes + l << ", term " << t << ", colour " << c);
                    const double lane_value = beta[t][c][l];
                    CHECK(std::memcmp(&lane_value, &beta1[t * 3 + c], sizeof(double)) == 0);
                    ++compared;
                }
        }
    }
    CHECK(compared == windows * n * 3);
}

TEST_CASE("nfor input: a missing channel and a NaN feature are named", "[denoise]") {
    const SyntheticImage s = textured_image(8, 6, 1, 0.1f);
    ExrChannels channels = as_channels(s.input);
    REQUIRE_NOTHROW(denoise::nfor_input(channels, "in.exr"));
    ExrChannels missing = channels;
    missing.channels.erase("Odd.Ns.Y");
    CHECK_THROWS_WITH(denoise::nfor_input(missing, "in.exr"), Catch::Contains("'in.exr' has no channel 'Odd.Ns.Y'"));
    ExrChannels nan = channels;
    nan.channels["Ns.X"][2 * 8 + 5] = std::nanf("");
    CHECK_THROWS_WITH(denoise::nfor_input(nan, "in.exr"), Catch::Contains("channel 'Ns.X' is NaN at pixel (5, 2)"));
    ExrChannels negative = channels;
    negative.channels["AlbedoVariance.G"][0] = -1.0f;
    CHECK_THROWS_WITH(denoise::nfor_input(negative, "in.exr"), Catch::Contains("channel 'AlbedoVariance.G' is negative at pixel (0, 0)"));
}

TEST_CASE("nfor: the vectorizable exp of the NL-means weights is the library's to a few float ulps", "[denoise]") {
    double worst = 0.0;
    for (int i = 0; i < 870000; ++i) {
        const float d = float(i) * 1e-4f;  // 0 to 87: every reduction interval, 2^0 down to 2^-125
        const double exact = std::exp(-double(d));
        worst = std::max(worst, std::abs(double(denoise::exp_weight(d)) / exact - 1.0));
    }
    INFO("largest relative error " << worst);
    CHECK(worst < 5e-7);
    CHECK(denoise::exp_weight(0.0f) == 1.0f);
    CHECK(denoise::exp_weight(-3.0f) == 1.0f);  // a distance below 0 is a pixel as alike as itself
    CHECK(denoise::exp_weight(87.5f) == 0.0f);  // past float's normal range
    CHECK(denoise::exp_weight(1e4f) == 0.0f);   // the capped distance
}

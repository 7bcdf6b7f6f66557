#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "raytracer/image/diff.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"

using namespace sweeptrace;

namespace {

Image flat(int w, int h, glm::vec3 v) {
    Image image(w, h);
    for (auto& p : image.pixels) p = v;
    return image;
}

}  // namespace

TEST_CASE("diff metrics on images with a known difference", "[image][diff]") {
    // 10 x 10 grey; 4 pixels raised by 0.2 in red only, in linear space.
    const Image a = flat(10, 10, glm::vec3(0.5f));
    Image b = a;
    for (int i = 0; i < 4; ++i) b.at(i, 3).r += 0.2f;
    DiffOptions linear;
    linear.space = DiffSpace::Linear;
    linear.pixel_threshold = 0.1;
    const DiffMetrics m = compare_images(a, b, linear);
    CHECK(m.rmse == Approx(std::sqrt(4 * 0.04 / 300.0)).epsilon(1e-5));
    CHECK(m.psnr == Approx(20.0 * std::log10(1.0 / m.rmse)));
    CHECK(m.mean_abs == Approx(4 * 0.2 / 300.0).epsilon(1e-5));
    CHECK(m.max_abs == Approx(0.2).epsilon(1e-5));
    CHECK(m.max_y == 3);
    CHECK(m.share_over == Approx(0.04));
    // Display space: the same pixels differ by the difference of their sRGB encodings.
    const DiffMetrics d = compare_images(a, b, DiffOptions{});
    CHECK(d.max_abs == Approx(srgb_encode(0.7f) - srgb_encode(0.5f)).epsilon(1e-5));
    // Identical images: zero everywhere, infinite PSNR.
    const DiffMetrics same = compare_images(a, a);
    CHECK(same.rmse == 0.0);
    CHECK(std::isinf(same.psnr));
    CHECK(same.share_over == 0.0);
    CHECK(same.mean_delta_e == 0.0);
}

TEST_CASE("diff: the simplified perceptual metric ignores fine noise more than a flat shift", "[image][diff]") {
    // Same RMSE, two kinds of difference: a +-e checkerboard (averages out under the 1 px blur)
    // and a uniform +e shift (does not). The blurred delta E must tell them apart.
    const float e = 0.05f;
    const Image base = flat(32, 32, glm::vec3(0.3f));
    Image checker = base, shifted = base;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            checker.at(x, y) += glm::vec3((x + y) % 2 ? e : -e);
            shifted.at(x, y) += glm::vec3(e);
        }
    DiffOptions linear;
    linear.space = DiffSpace::Linear;
    const DiffMetrics mc = compare_images(base, checker, linear), ms = compare_images(base, shifted, linear);
    CHECK(mc.rmse == Approx(ms.rmse).epsilon(1e-4));
    CHECK(mc.mean_delta_e < 0.1 * ms.mean_delta_e);
    CHECK(ms.share_delta_e_over_jnd == 1.0);  // a 0.05 shift at 0.3 grey is ~ 4 delta E
}

TEST_CASE("diff: sizes must match, non-finite pixels count as differing", "[image][diff]") {
    CHECK_THROWS_AS(compare_images(Image(4, 4), Image(4, 5)), InputError);
    Image a = flat(4, 4, glm::vec3(0.5f)), b = a;
    b.at(1, 1).g = std::nanf("");
    const DiffMetrics m = compare_images(a, b);
    CHECK(m.non_finite_b == 1);
    CHECK(m.non_finite_a == 0);
    CHECK(m.share_over == Approx(1.0 / 16.0));
    CHECK(std::isfinite(m.rmse));
    const Image heat = difference_heatmap(a, b, DiffOptions{}, 0.2);
    CHECK(heat.at(1, 1) == glm::vec3(1.0f, 0.0f, 1.0f));
    CHECK(heat.at(0, 0) == glm::vec3(0.0f));
}

TEST_CASE("heatmap: black for equal, red at and above the scale", "[image][diff]") {
    const Image a = flat(3, 1, glm::vec3(0.0f));
    Image b = a;
    b.at(1, 0) = glm::vec3(1.0f);
    DiffOptions linear;
    linear.space = DiffSpace::Linear;
    const Image heat = difference_heatmap(a, b, linear, 0.5);
    CHECK(heat.at(0, 0) == glm::vec3(0.0f));
    CHECK(heat.at(1, 0) == glm::vec3(1.0f, 0.0f, 0.0f));
}

TEST_CASE("normal quantile matches known values", "[image][diff]") {
    CHECK(normal_two_sided_quantile(0.05) == Approx(1.959964).epsilon(1e-6));
    CHECK(normal_two_sided_quantile(1e-4) == Approx(3.890592).epsilon(1e-6));
    CHECK(normal_two_sided_quantile(1e-9) == Approx(6.109410).epsilon(1e-6));
}

TEST_CASE("block test: accepts pure noise of the stated variance, rejects a small bias", "[image][diff]") {
    // Synthetic "renders": golden 0.4 everywhere (exact float, no 8-bit bound), actual = golden +
    // Gaussian noise of known sigma per pixel. 64 x 64 pixels, 8 x 8 blocks -> 192 tests.
    const int w = 64, h = 64;
    const float sigma = 0.05f;
    const Image golden = flat(w, h, glm::vec3(0.4f));
    const Image variance = flat(w, h, glm::vec3(sigma * sigma));
    BlockTestOptions options;
    options.golden_is_8bit = false;
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.0f, sigma);
    int rejected = 0;
    for (int trial = 0; trial < 20; ++trial) {
        Image actual = golden;
        for (auto& p : actual.pixels) p += glm::vec3(noise(rng), noise(rng), noise(rng));
        rejected += !block_test(golden, actual, variance, options).pass();
    }
    CHECK(rejected == 0);  // family-wise false alarm 1e-4 per trial
    // A bias of 0.04 in one 8 x 8 block: block sigma is 0.05 / 8 = 0.00625, so z ~ 6.4 > limit ~ 5.0.
    Image biased = golden;
    for (int y = 8; y < 16; ++y)
        for (int x = 16; x < 24; ++x) biased.at(x, y).g += 0.04f;
    const BlockTestResult r = block_test(golden, biased, variance, options);
    CHECK_FALSE(r.pass());
    CHECK(r.worst_bx == 2);
    CHECK(r.worst_by == 1);
    CHECK(r.worst_channel == 1);
    CHECK(r.blocks_over == 1);
    CHECK(r.z_limit == Approx(normal_two_sided_quantile(1e-4 / 192)));
}

TEST_CASE("block test: the golden's 8-bit rounding is tolerated, not more", "[image][diff]") {
    // A golden stored as 8-bit sRGB differs from the truth by up to half a code; a noise-free
    // actual equal to the truth must pass, one a full code step away must not.
    const float truth = 0.2f;
    const float stored = srgb_decode(std::round(srgb_encode(truth) * 255.0f) / 255.0f);
    const Image golden = flat(16, 16, glm::vec3(stored));
    const Image zero(16, 16);
    CHECK(block_test(golden, flat(16, 16, glm::vec3(truth)), zero).pass());
    const float next = srgb_decode((std::round(srgb_encode(truth) * 255.0f) + 1.0f) / 255.0f);
    CHECK_FALSE(block_test(golden, flat(16, 16, glm::vec3(next)), zero).pass());
}

TEST_CASE("combine_halves: mean and variance of the mean from two renders", "[image][diff]") {
    Image a = flat(1, 1, glm::vec3(0.2f)), b = flat(1, 1, glm::vec3(0.6f));
    a.at(0, 0).b = 3.0f;  // linear, unclamped
    const MeanAndVariance mv = combine_halves(a, b);
    CHECK(mv.mean.at(0, 0).r == Approx(0.4f));
    CHECK(mv.variance.at(0, 0).r == Approx(0.04f));
    CHECK(mv.mean.at(0, 0).b == Approx(1.8f));
    CHECK(mv.variance.at(0, 0).b == Approx(1.44f));
}

TEST_CASE("block test: a saturated 8-bit golden is one-sided", "[image][diff]") {
    // Golden pixels at code 255 only say "1 or more": a render at 5 agrees, one at 0.5 does not.
    const Image golden = flat(16, 16, glm::vec3(1.0f, 0.5f, 0.5f));
    const Image zero(16, 16);
    const float g = srgb_decode(std::round(srgb_encode(0.5f) * 255.0f) / 255.0f);
    CHECK(block_test(golden, flat(16, 16, glm::vec3(5.0f, g, g)), zero).pass());
    const BlockTestResult dark = block_test(golden, flat(16, 16, glm::vec3(0.5f, g, g)), zero);
    CHECK_FALSE(dark.pass());
    CHECK(dark.worst_channel == 0);
}

TEST_CASE("block test: the reference's variance covers rare paths the render missed", "[image][diff]") {
    // A render that caught none of a rare bright path reports zero variance; the golden, which
    // did, says how far a correct render may fall below it.
    const Image golden = flat(8, 8, glm::vec3(0.01f));
    const Image zero(8, 8), dark(8, 8);
    BlockTestOptions options;
    options.golden_is_8bit = false;
    CHECK_FALSE(block_test(golden, dark, zero, options).pass());  // variance 0: any difference is infinite z
    const Image null_variance = flat(8, 8, glm::vec3(0.01f));    // e.g. value 1 with p = 0.01 per sample, 1 spp
    options.null_variance = &null_variance;
    const BlockTestResult r = block_test(golden, dark, zero, options);
    CHECK(r.pass());
    CHECK(r.max_z == Approx(0.01 / (0.1 / 8)));  // mean difference over sqrt(64 x 0.01) / 64
}

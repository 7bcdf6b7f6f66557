// Adaptive sampling (RenderOptions::adaptive, render/adaptive_sampling.hpp): the allocation's
// rules, the same image at any thread count, each pixel's samples being 0..n_p-1 of its own
// sequence (so its sums and variance are a uniform render's of n_p), and no bias against a long
// uniform render by a block z-test. Farm parts and --time: test_render_adaptive_farm.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <vector>

#include "cli_run.hpp"
#include "image_test_support.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/render/adaptive_sampling.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "render_test_stats.hpp"

using namespace sweeptrace;

namespace {

Scene adaptive_cornell(int width, int height) {
    Scene s = load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / "cornell-box.json");
    s.film.width = width;
    s.film.height = height;
    return s;
}

RenderOptions adaptive_options(int spp, std::uint64_t seed, bool adaptive) {
    RenderOptions o;
    o.spp = spp;
    o.seed = seed;
    o.max_depth = 6;
    o.adaptive = adaptive;
    o.threads = 2;
    return o;
}

}  // namespace

TEST_CASE("adaptive: tile weights follow the capped error, keep a uniform share and average 1", "[render][adaptive]") {
    const AdaptiveTiles tiles(40, 20);  // 5 x 3 tiles, the last row 4 pixels high
    REQUIRE(tiles.count() == 15);
    CHECK(tiles.pixels_in(0) == 64);
    CHECK(tiles.pixels_in(14) == 32);
    auto pixel_mean = [&](const std::vector<double>& w) {
        double sum = 0.0;
        for (int t = 0; t < 15; ++t) sum += w[static_cast<std::size_t>(t)] * tiles.pixels_in(t);
        return sum / (40.0 * 20.0);
    };

    SECTION("equal errors (or none) give every tile weight 1") {
        for (const double e : {0.0, 2.5})
            for (const double w : adaptive_tile_weights(tiles, std::vector<double>(15, e))) CHECK(w == 1.0);
    }
    SECTION("a noisier tile weighs more, in proportion above the uniform share; the mean is 1") {
        std::vector<double> e(15, 1.0);
        e[3] = e[4] = 3.0;  // two, so the 95th percentile (the second largest of 15) does not cap them
        e[7] = 0.0;
        const std::vector<double> w = adaptive_tile_weights(tiles, e);
        CHECK(pixel_mean(w) == Approx(1.0).epsilon(1e-12));
        CHECK(w[7] == Approx(kAdaptiveUniformShare));  // error 0: the uniform share alone
        CHECK((w[3] - kAdaptiveUniformShare) == Approx(3.0 * (w[0] - kAdaptiveUniformShare)));
    }
    SECTION("one tile's firefly counts only as the 95th percentile's error") {
        std::vector<double> e(15, 1.0);
        e[5] = 1e9;
        e[6] = 2.0;  // the 95th percentile of 15 tiles is the second largest (index 13 of 0..14)
        const std::vector<double> w = adaptive_tile_weights(tiles, e);
        CHECK(w[5] == w[6]);
        CHECK(w[5] > w[0]);
    }
    SECTION("a pixel's count only grows with the budget, and the image's mean is the budget to within 1/2") {
        std::vector<double> e(15, 1.0);
        e[2] = e[9] = 4.0;
        e[11] = 0.0;
        const std::vector<double> w = adaptive_tile_weights(tiles, e);
        for (const std::int64_t t : {std::int64_t{1}, std::int64_t{7}, std::int64_t{24}, std::int64_t{1000}, std::int64_t{1} << 20}) {
            double total = 0.0;
            for (int tile = 0; tile < 15; ++tile) {
                const double wt = w[static_cast<std::size_t>(tile)];
                CHECK(adaptive_count(wt, t) >= adaptive_count(wt, t - 1));
                total += double(adaptive_count(wt, t)) * tiles.pixels_in(tile);
            }
            INFO("budget " << t);
            CHECK(std::fabs(total / (40.0 * 20.0) - double(t)) <= 0.5);
        }
        CHECK(adaptive_count(w[0], 0) == 0);
    }
}

TEST_CASE("adaptive: a pixel's weight does not depend on its own samples (checkerboard cross-fit), and averages 1", "[render][adaptive]") {
    // Made-up pilot sums of a 27x18 image (uneven tiles, a 3x2 corner tile), 16 samples a pixel,
    // noisier towards the right; then one pixel at a time given a firefly.
    const int w = 27, h = 18, n = 16;
    const AdaptiveTiles tiles(w, h);
    std::vector<PixelSum> sums(static_cast<std::size_t>(w) * h);
    std::vector<glm::dvec3> sq(sums.size());
    std::uint64_t state = 12345;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * 0x1p-53;
    };
    for (std::size_t p = 0; p < sums.size(); ++p) {
        bool clamped = false;
        const double spread = 0.1 + double(p % w) / w;
        for (int k = 0; k < n; ++k) {
            const float v = static_cast<float>(0.5 + spread * (next() - 0.5));
            add_sample(sums[p], glm::vec3(v), clamped);
            sq[p] += glm::dvec3(double(v) * v);
        }
    }
    for (const AdaptiveError rule : {AdaptiveError::Mse, AdaptiveError::Relative}) {
        const std::vector<double> base = adaptive_pixel_weights(tiles, rule, sums, sq, n);
        // Each colour of the checkerboard has mean weight 1, so the image has too.
        double mean[2] = {0.0, 0.0}, pixels[2] = {0.0, 0.0};
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                mean[(x + y) & 1] += base[static_cast<std::size_t>(y) * w + x];
                pixels[(x + y) & 1] += 1.0;
            }
        CHECK(mean[0] / pixels[0] == Approx(1.0).epsilon(1e-12));
        CHECK(mean[1] / pixels[1] == Approx(1.0).epsilon(1e-12));
        CHECK(*std::max_element(base.begin(), base.end()) > 1.2);  // the allocation is uneven
        // Pixels of quiet tiles (a tile already at the 95th percentile's cap would not move).
        for (const std::size_t p : {std::size_t{0}, std::size_t{5 * w + 3}, std::size_t{(h - 1) * w + 2}}) {
            std::vector<PixelSum> s2 = sums;
            std::vector<glm::dvec3> q2 = sq;
            bool clamped = false;
            add_sample(s2[p], glm::vec3(50.0f), clamped);
            q2[p] += glm::dvec3(2500.0);
            const std::vector<double> moved = adaptive_pixel_weights(tiles, rule, s2, q2, n);
            INFO("pixel " << p);
            CHECK(moved[p] == base[p]);  // exactly: nothing of its own samples is read
            // ... while its firefly does move the weights of the other colour (the test can see one).
            CHECK(moved[p + 1] != base[p + 1]);
        }
    }
}

TEST_CASE("adaptive: same image at any thread count, and pixel p holds samples 0..n_p-1 of its sequence", "[render][adaptive]") {
    const Scene s = adaptive_cornell(40, 32);
    const std::unique_ptr<Accel> accel = make_accel(AccelKind::Bvh, s);
    RenderOptions o = adaptive_options(40, 5, true);
    o.threads = 1;
    const RenderResult one = render(s, *accel, o);
    o.threads = 3;
    const RenderResult three = render(s, *accel, o);
    CHECK(testing::bitwise_equal(one.image, three.image));
    CHECK(testing::bitwise_equal(one.variance, three.variance));
    CHECK(one.sums == three.sums);
    REQUIRE(one.pixel_samples == three.pixel_samples);

    // The budget is spent to within half a sample per pixel, and unevenly: the light and the
    // walls' noise differ.
    const std::vector<int>& n = one.pixel_samples;
    REQUIRE(n.size() == 40u * 32u);
    const std::int64_t total = std::accumulate(n.begin(), n.end(), std::int64_t{0});
    CHECK(std::llabs(total - 40 * 40 * 32) <= 40 * 32 / 2);
    CHECK(one.stats.samples == static_cast<std::uint64_t>(total));
    CHECK(one.stats.completed_spp == 40);
    const auto [lo, hi] = std::minmax_element(n.begin(), n.end());
    CHECK(*lo >= kAdaptivePilotSpp);
    CHECK(*lo < 40);
    CHECK(*hi > 48);

    // Pixels with the fewest and the most samples: their sums and variance are those of a
    // uniform render with that spp, bit for bit (same samples, same order, same arithmetic).
    for (const auto it : {lo, hi}) {
        const auto p = static_cast<std::size_t>(it - n.begin());
        const RenderResult uniform = render(s, *accel, adaptive_options(*it, 5, false));
        INFO("pixel " << p << " with " << *it << " samples");
        CHECK(uniform.sums[p] == one.sums[p]);
        CHECK(std::memcmp(&uniform.variance.pixels[p], &one.variance.pixels[p], sizeof(glm::vec3)) == 0);
        CHECK(std::memcmp(&uniform.image.pixels[p], &one.image.pixels[p], sizeof(glm::vec3)) == 0);
    }

    // At or below the pilot's spp the render is the uniform one.
    const RenderResult small = render(s, *accel, adaptive_options(kAdaptivePilotSpp, 5, true));
    CHECK(testing::bitwise_equal(small.image, render(s, *accel, adaptive_options(kAdaptivePilotSpp, 5, false)).image));

    // What it cannot do is refused.
    RenderOptions bad = adaptive_options(40, 5, true);
    bad.integrator = IntegratorKind::Bdpt;
    CHECK_THROWS_AS(render(s, *accel, bad), std::invalid_argument);
    bad = adaptive_options(40, 5, true);
    bad.guiding = true;
    CHECK_THROWS_AS(render(s, *accel, bad), std::invalid_argument);
}

TEST_CASE("adaptive: unbiased against a long uniform render of cornell-box (8x8 block z-test)", "[render][adaptive]") {
    // Independent samples, so each pixel's stated variance is exactly what its mean's is
    // estimated by; the adaptive render's per-pixel variances come from each pixel's own n_p.
    const Scene s = adaptive_cornell(48, 48);
    const std::unique_ptr<Accel> accel = make_accel(AccelKind::Bvh, s);
    const AdaptiveError metric = GENERATE(AdaptiveError::Mse, AdaptiveError::Relative);
    RenderOptions ao = adaptive_options(64, 11, true);
    ao.adaptive_error = metric;
    ao.sampler = SamplerKind::Independent;
    RenderOptions uo = adaptive_options(512, 12, false);
    uo.sampler = SamplerKind::Independent;
    const RenderResult a = render(s, *accel, ao);
    const RenderResult u = render(s, *accel, uo);
    // z of each 8x8 block's mean per channel; also a 3% brighter copy, which must be caught, so
    // the test has the power to see a bias that size.
    auto block_z = [&](float scale, double& max_z, double& mean_z2) {
        max_z = 0.0;
        mean_z2 = 0.0;
        int tests = 0;
        for (int by = 0; by < 6; ++by)
            for (int bx = 0; bx < 6; ++bx)
                for (int c = 0; c < 3; ++c) {
                    double da = 0.0, du = 0.0, va = 0.0, vu = 0.0;
                    for (int y = by * 8; y < by * 8 + 8; ++y)
                        for (int x = bx * 8; x < bx * 8 + 8; ++x) {
                            const std::size_t p = static_cast<std::size_t>(y) * 48 + x;
                            da += scale * a.image.pixels[p][c];
                            va += scale * scale * a.variance.pixels[p][c];
                            du += u.image.pixels[p][c];
                            vu += u.variance.pixels[p][c];
                        }
                    if (va + vu <= 0.0) continue;
                    const double z = (da - du) / std::sqrt(va + vu);
                    max_z = std::max(max_z, std::fabs(z));
                    mean_z2 += z * z;
                    ++tests;
                }
        mean_z2 /= tests;
    };
    double max_z = 0.0, mean_z2 = 0.0;
    block_z(1.0f, max_z, mean_z2);
    INFO((metric == AdaptiveError::Mse ? "mse" : "relative") << ": max |z| " << max_z << ", mean z^2 " << mean_z2);
    CHECK(max_z < test::z_bound(108));
    CHECK(mean_z2 < 2.0);  // E[z^2] = 1 without bias (a few blocks' variance estimates are noisy)
    double max_bright = 0.0, mean_bright = 0.0;
    block_z(1.03f, max_bright, mean_bright);
    INFO("3% brighter: max |z| " << max_bright << ", mean z^2 " << mean_bright);
    CHECK(mean_bright > 3.0);
}

TEST_CASE("render cli: --adaptive on renders and says so, and what it cannot do exits 2 naming why", "[render][cli][adaptive]") {
    const std::filesystem::path dir = std::filesystem::path(SWEEPTRACE_BINARY_DIR) / "render-adaptive-tests";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string scene = std::string(SWEEPTRACE_SOURCE_DIR) + "/scenes/cornell-box.json";
    const std::string base = "render " + scene + " --width 24 --height 24 --spp 24 --adaptive on ";
    const auto ok = test::run_sweeptrace(dir, base + "-o a.pfm --variance v.pfm");
    INFO(ok.err);
    REQUIRE(ok.exit_code == 0);
    CHECK(ok.err.find("24 spp adaptive (mean)") != std::string::npos);
    CHECK(read_image(dir / "v.pfm").width == 24);
    // diff's noise test takes the adaptive render's per-pixel variances as any other: a uniform
    // render of another seed is within noise of it.
    const auto u = test::run_sweeptrace(dir, "render " + scene + " --width 24 --height 24 --spp 64 --seed 9 --quiet -o u.pfm --variance uv.pfm");
    REQUIRE(u.exit_code == 0);
    const auto d = test::run_sweeptrace(dir, "diff a.pfm u.pfm --variance-a v.pfm --variance-b uv.pfm");
    INFO(d.err);
    CHECK(d.exit_code == 0);
    for (const std::string extra : {"--integrator bdpt -o b.png", "--integrator vcm -o b.png", "--guiding on -o g.png",
                                    "--forensics f.json -o f.png"}) {
        const auto r = test::run_sweeptrace(dir, base + extra);
        INFO(extra << ": " << r.err);
        CHECK(r.exit_code == 2);
        CHECK(r.err.rfind("sweeptrace: error: --adaptive on ", 0) == 0);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
    CHECK_FALSE(std::filesystem::exists(dir / "b.png"));
}

// The numbers behind `sweeptrace reference-check` (image/reference_compare.hpp): the box
// downsampling over whole source pixels, the reference's noise estimated from its residuals, the
// block z-test with both variances, and the stand-in mask scene (scene/stand_in_mask.hpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "raytracer/image/reference_compare.hpp"
#include "raytracer/scene/stand_in_mask.hpp"

using namespace sweeptrace;

TEST_CASE("reference downsampling: the mean of whole source pixels, and a non-finite one masks its pixel", "[reference]") {
    Image src(4, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) src.at(x, y) = glm::vec3(float(x + 4 * y));
    src.at(3, 1) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    const DownsampledReference d = downsample_reference(src, 2);
    REQUIRE(d.image.width == 2);
    REQUIRE(d.image.height == 1);
    CHECK(d.image.at(0, 0).x == Approx((0 + 1 + 4 + 5) / 4.0));
    CHECK(d.valid[0] == 1);
    CHECK(d.valid[1] == 0);  // (3, 1) is NaN
    CHECK(d.image.at(1, 0).x == Approx((2 + 3 + 6) / 3.0));  // the finite ones, for the picture only
}

TEST_CASE("reference noise: flat image plus seeded noise of sigma 0.1 gives the variance of each pixel's mean", "[reference]") {
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.0f, 0.1f);
    Image src(256, 256);
    for (auto& p : src.pixels) p = glm::vec3(0.5f + noise(rng), 0.5f + noise(rng), 0.5f + noise(rng));
    const DownsampledReference d = downsample_reference(src, 4);
    double sum = 0.0;
    for (const auto& v : d.variance.pixels) sum += v.y;
    // sigma^2 / 16 source pixels = 6.25e-4; 64x64 pixels of 16 estimates each: ~1 % spread.
    CHECK(sum / double(d.variance.pixels.size()) == Approx(0.01 / 16.0).epsilon(0.05));
    // A sharp edge is not noise, but counts as such: the estimate only grows (the test gets lenient).
    Image edge(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 8; x < 16; ++x) edge.at(x, y) = glm::vec3(1.0f);
    const DownsampledReference e = downsample_reference(edge, 4);
    CHECK(e.variance.at(0, 0).x == 0.0f);
    CHECK(e.variance.at(1, 0).x > 0.0f);
}

TEST_CASE("block comparison: z from both variances, shares, median error and mean ratio", "[reference]") {
    const int w = 16, h = 8;  // two 8x8 blocks
    Image ref(w, h), ours(w, h), var_ours(w, h), var_ref(w, h);
    for (auto& p : ref.pixels) p = glm::vec3(1.0f);
    for (auto& v : var_ours.pixels) v = glm::vec3(0.01f);
    for (auto& v : var_ref.pixels) v = glm::vec3(0.03f);
    // A block mean's sigma: sqrt(64 x 0.04) / 64 = 0.025. Left block +4 sigma in green only, right
    // block -2 sigma in every channel.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ours.at(x, y) = x < 8 ? glm::vec3(1.0f, 1.1f, 1.0f) : glm::vec3(0.95f);
    std::vector<std::uint8_t> valid(static_cast<std::size_t>(w) * h, 1);
    const BlockComparison c = compare_blocks(ours, var_ours, ref, var_ref, valid);
    REQUIRE(c.tested == 2);
    CHECK(c.z[0] == Approx(4.0));
    CHECK(c.z[1] == Approx(-2.0));
    CHECK(c.share_within_3 == Approx(0.5));
    CHECK(c.share_within_5 == Approx(1.0));
    CHECK(c.median_relative_error == Approx(0.5 * (0.1 / 3.0 - 0.05)));
    CHECK(c.mean_ratio.x == Approx(0.975));
    CHECK(c.mean_ratio.y == Approx(1.025));
    // Masking more than half of the left block leaves it untested and out of the means.
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 8; ++x) valid[static_cast<std::size_t>(y) * w + x] = 0;
    const BlockComparison m = compare_blocks(ours, var_ours, ref, var_ref, valid);
    CHECK(m.tested == 1);
    CHECK(std::isnan(m.z[0]));
    CHECK(m.share_within_3 == Approx(1.0));
    CHECK(m.valid_share == Approx(88.0 / 128.0));
    CHECK(m.mean_ratio.y == Approx((24 * 1.1 + 64 * 0.95) / 88.0));
    // The picture: three panels of the render's size.
    const Image pic = comparison_picture(ours, ref, valid, m);
    CHECK(pic.width == 3 * w);
    CHECK(pic.height == h);
}

TEST_CASE("stand-in mask scene: only surfaces reading a flat 8x8 texture emit, diffuse goes black, mirrors stay", "[reference]") {
    Scene s;
    Texture flat;
    flat.kind = Texture::Kind::Image;
    auto img = std::make_shared<Image>(8, 8);
    for (auto& p : img->pixels) p = glm::vec3(0.5f);
    flat.image = img;
    flat.image_file = "/nowhere/wood.tga";
    Texture real = flat;
    auto detailed = std::make_shared<Image>(8, 8);
    detailed->at(3, 3) = glm::vec3(1.0f);
    real.image = detailed;
    real.image_file = "/nowhere/real.tga";
    s.textures = {real, flat};
    Material wood, wall, mirror, lamp;
    wood.albedo_texture = 1;
    wall.albedo_texture = 0;
    mirror.type = Material::Type::Metal;
    lamp.emission = glm::vec3(5.0f);
    s.materials = {wood, wall, mirror, lamp};
    s.background.color = glm::vec3(1.0f);
    s.lights.resize(1);

    const std::vector<int> found = stand_in_textures(s, {}, true);
    REQUIRE(found == std::vector<int>{1});
    CHECK(stand_in_textures(s, {"/nowhere/real.tga"}, false) == std::vector<int>{0});
    bool any = false;
    const Scene m = stand_in_mask_scene(s, found, any);
    CHECK(any);
    CHECK(m.materials[0].emission == glm::vec3(1.0f));
    CHECK(m.materials[0].two_sided_emission);
    CHECK(m.materials[0].albedo == glm::vec3(0.0f));
    CHECK(m.materials[1].emission == glm::vec3(0.0f));
    CHECK(m.materials[1].albedo == glm::vec3(0.0f));
    CHECK(m.materials[1].albedo_texture == -1);
    CHECK(m.materials[2].type == Material::Type::Metal);
    CHECK(m.materials[2].albedo == glm::vec3(0.8f));
    CHECK(m.materials[3].emission == glm::vec3(0.0f));
    CHECK(m.lights.empty());
    CHECK(m.background.color == glm::vec3(0.0f));
    bool none = true;
    stand_in_mask_scene(s, {}, none);
    CHECK_FALSE(none);
}

// 16 batches of a flat 64x64 image of 1, each pixel's noise the sum of its own and one shared by
// its 4x4 patch (as one light-tracing splat lands on neighbouring pixels); `whole_variance` the
// exact per-pixel variance of the batches' mean, what summing pixels assumes is all there is.
namespace {
struct RcSplatLike {
    std::vector<Image> batches;
    Image mean, variance;
};
RcSplatLike rc_splat_like(float sigma_pixel, float sigma_patch, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> n(0.0f, 1.0f);
    constexpr int kK = 16, kW = 64;
    RcSplatLike r{{}, Image(kW, kW), Image(kW, kW)};
    for (int b = 0; b < kK; ++b) {
        Image im(kW, kW);
        std::vector<glm::vec3> patch(16 * 16);
        for (auto& p : patch) p = glm::vec3(n(rng), n(rng), n(rng)) * sigma_patch;
        for (int y = 0; y < kW; ++y)
            for (int x = 0; x < kW; ++x)
                im.at(x, y) = glm::vec3(1.0f) + glm::vec3(n(rng), n(rng), n(rng)) * sigma_pixel + patch[(y / 4) * 16 + x / 4];
        for (std::size_t i = 0; i < im.pixels.size(); ++i) r.mean.pixels[i] += im.pixels[i] / float(kK);
        r.batches.push_back(std::move(im));
    }
    for (auto& v : r.variance.pixels) v = glm::vec3((sigma_pixel * sigma_pixel + sigma_patch * sigma_patch) / float(kK));
    return r;
}
}  // namespace

TEST_CASE("block variance from replicas: correlated pixels' blocks vary 8.5x their pixel sum, independent ones 1x, and the scaled z-test is right", "[reference]") {
    const std::vector<std::uint8_t> all(64 * 64, 1);
    // Independent pixels: the replicas agree with the pixel sum.
    const RcSplatLike ind = rc_splat_like(0.1f, 0.0f, 3);
    CHECK(block_variance_scale(ind.batches, ind.variance, all) == Approx(1.0).epsilon(0.15));
    // Equal pixel and patch noise: a block's 4 patches of 16 pixels give 64 s^2 + 4 * 256 s^2
    // against the sum's 64 * 2 s^2, 8.5 times.
    const RcSplatLike cor = rc_splat_like(0.1f, 0.1f, 4);
    const double scale = block_variance_scale(cor.batches, cor.variance, all);
    CHECK(scale == Approx(8.5).epsilon(0.2));
    CHECK(block_variance_scale({cor.batches.front()}, cor.variance, all) == 1.0);  // one batch: nothing measured
    // The truth (a flat 1, without noise) against the correlated mean: summing pixel variances
    // flags blocks that are only noise; the replicas' measure does not.
    Image truth(64, 64), zero(64, 64);
    for (auto& p : truth.pixels) p = glm::vec3(1.0f);
    const BlockComparison plain = compare_blocks(cor.mean, cor.variance, truth, zero, all);
    const BlockComparison scaled = compare_blocks(cor.mean, cor.variance, truth, zero, all, 8, scale);
    INFO("scale " << scale << ", within |z| < 3: plain " << plain.share_within_3 << ", scaled " << scaled.share_within_3);
    CHECK(plain.share_within_3 < 0.6);
    CHECK(scaled.share_within_3 >= 0.95);
}

// The experiments behind docs/reference-deviations-veach-bidir.md: Bitterli's veach-bidir
// (../shared/bitterli/veach-bidir) rendered small through the pbrt importer at the reference's
// depth (7 path vertices after the camera), first bdpt against the path tracer (is our bdpt
// unbiased on it?), then bdpt against TungstenRender.exr box-filtered to the same size with the
// lamps' conductor as the pbrt-v4 file has it (GGX, alpha 0.25) and as Tungsten's own form of the
// scene has it (Beckmann, alpha 0.25). Block z-tests take our block variance from 16 independent
// batches of each render (image/reference_compare.hpp, block_variance_scale), since bdpt's
// splats correlate neighbouring pixels. Each prints its figures and asserts the explanation.
// Hidden from the default suite ([.]: about a CPU minute each); run them with
//   ./build/tests/raytracer_tests "[reference-deviations]" -s
// They say SKIPPED and pass without ../shared/bitterli.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/accel/accel.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/reference_compare.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"
#include "raytracer/scene/scene.hpp"

using namespace sweeptrace;

namespace {

// Tungsten's max_bounces b was written as the file's maxdepth b + 1 = 7; its bidirectional path
// tracer, which rendered this reference, makes paths of at most b = 6 vertices after the camera
// (s + t <= b + 1 with the camera vertex counted), as its path tracer does.
constexpr int kVbFileDepth = 7, kVbDepth = 6;
constexpr int kVbBatches = 16;

std::filesystem::path vb_folder() { return std::filesystem::path(SWEEPTRACE_SHARED_DIR) / "bitterli" / "veach-bidir"; }

bool vb_have() {
    if (std::filesystem::is_regular_file(vb_folder() / "scene-v4.pbrt")) return true;
    std::printf("SKIPPED: needs %s (the shared/ folder beside the checkout)\n", vb_folder().string().c_str());
    return false;
}

// The pbrt-v4 file as our importer reads it, at `width` px, with a box pixel filter (the box
// downsampling of the reference averages the same footprint).
Scene vb_scene(int width, IntegratorKind integrator) {
    std::vector<std::string> warnings;
    Scene s = load_pbrt_scene(vb_folder() / "scene-v4.pbrt", false, warnings);
    s.film.height = s.film.height * width / s.film.width;
    s.film.width = width;
    s.film.filter = FilterSpec{};
    s.film.integrator = integrator;
    return s;
}

struct VbRender {
    Image image, variance;  // the whole render's mean and the per-pixel variance of that mean
    double block_scale = 1.0;
};

// `spp` samples in kVbBatches disjoint ranges (together the samples of one render), independent
// sampler; the replicas' block variance over the pixel-variance sum, pooled over the image.
VbRender vb_render(const Scene& s, int spp, std::uint64_t seed, int block, int depth = kVbDepth) {
    const auto accel = make_accel(AccelKind::Bvh, s);
    std::vector<Image> batches;
    VbRender out{Image(s.film.width, s.film.height), Image(s.film.width, s.film.height)};
    const int per = spp / kVbBatches;
    for (int b = 0; b < kVbBatches; ++b) {
        RenderOptions o;
        o.spp = per;
        o.first_sample = b * per;
        o.max_depth = depth;
        o.seed = seed;
        o.sampler = SamplerKind::Independent;
        o.integrator = s.film.integrator;
        const RenderResult r = render(s, *accel, o);
        for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
            out.image.pixels[i] += r.image.pixels[i] / float(kVbBatches);
            out.variance.pixels[i] += r.variance.pixels[i] / float(kVbBatches * kVbBatches);
        }
        batches.push_back(r.image);
    }
    out.block_scale = block_variance_scale(batches, out.variance, std::vector<std::uint8_t>(out.image.pixels.size(), 1), block);
    return out;
}

Image vb_scaled(const VbRender& r) {
    Image v = r.variance;
    for (glm::vec3& p : v.pixels) p *= float(r.block_scale);
    return v;
}

void vb_print(const char* what, const BlockComparison& c) {
    std::printf("  %-52s mean %.4f %.4f %.4f, blocks |z|<3 %5.1f %% |z|<5 %5.1f %% (%zu), median block %+.2f %%\n", what,
                c.mean_ratio.x, c.mean_ratio.y, c.mean_ratio.z, 100.0 * c.share_within_3, 100.0 * c.share_within_5, c.tested,
                100.0 * c.median_relative_error);
}

}  // namespace

TEST_CASE("reference deviations: veach-bidir: our bdpt and our path tracer agree", "[.][reference-deviations]") {
    if (!vb_have()) return;
    // 32 x 32 px, 4 x 4 blocks (64 of them). The path tracer is noisy here (the lamps' light
    // reaches most of the room through a rough conductor or the table lamp's glass), so it gets
    // 16 times bdpt's samples; the z-test takes both renders' variances, each bdpt block's
    // scaled by its replicas' measure.
    constexpr int kBlock = 4;
    const VbRender bd = vb_render(vb_scene(32, IntegratorKind::Bdpt), 1024, 11, kBlock);
    const VbRender pt = vb_render(vb_scene(32, IntegratorKind::Path), 16384, 12, kBlock);
    const std::vector<std::uint8_t> all(bd.image.pixels.size(), 1);
    Image pt_var = vb_scaled(pt);
    const BlockComparison c = compare_blocks(bd.image, vb_scaled(bd), pt.image, pt_var, all, kBlock);
    std::printf("veach-bidir, 32 px, depth %d, bdpt 1024 spp against path 16384 spp (block variance x %.2f and x %.2f "
                "of the pixel sums, by %d batches)\n", kVbDepth, bd.block_scale, pt.block_scale, kVbBatches);
    vb_print("bdpt / path", c);
    CHECK(bd.block_scale > 1.0);  // the splats' correlation, measured
    CHECK(c.share_within_3 >= 0.9);
    CHECK(std::abs(c.median_relative_error) < 0.01);
    for (const double m : {c.mean_ratio.x, c.mean_ratio.y, c.mean_ratio.z}) CHECK(std::abs(m - 1.0) < 0.02);
}

TEST_CASE("reference deviations: veach-bidir: Tungsten's bdpt stops at 6 vertices after the camera and its lamps are Beckmann", "[.][reference-deviations]") {
    if (!vb_have()) return;
    // Two settings of the reference that the pbrt-v4 file does not carry, each alone not enough:
    // - depth: Tungsten's BidirectionalPathTracer::traceSample bounds every strategy by
    //   s + t <= max_bounces + 1 (s light vertices, t camera vertices, the camera's own counted),
    //   so with max_bounces 6 (the file's maxdepth 7) its longest path has 6 vertices after the
    //   camera, not the file's 7;
    // - the lamps: Tungsten's scene gives "Lamp" (the floor lamp's shade and stand, the table
    //   lamp) as rough_conductor, distribution beckmann, roughness 0.25 (its alpha); pbrt-v4's
    //   conductor is Trowbridge-Reitz (GGX) only, and the file keeps alpha 0.25 with it.
    constexpr int kBlock = 8;
    Scene s = vb_scene(64, IntegratorKind::Bdpt);
    const DownsampledReference ref = downsample_reference(read_image(vb_folder() / "TungstenRender.exr"), 1024 / 64);
    const auto judged = [&](int depth) {
        const VbRender r = vb_render(s, 1024, 21, kBlock, depth);
        return std::make_pair(compare_blocks(r.image, vb_scaled(r), ref.image, ref.variance, ref.valid, kBlock), r.block_scale);
    };
    const auto [ggx7, v1] = judged(kVbFileDepth);
    const auto [ggx6, v2] = judged(kVbDepth);
    for (Material& m : s.materials)
        if (m.name == "Lamp") m.microfacet = Material::Microfacet::Beckmann;
    const auto [beck7, v3] = judged(kVbFileDepth);
    const auto [beck6, v4] = judged(kVbDepth);
    std::printf("veach-bidir, 64 px, bdpt 1024 spp against Tungsten's reference (block variance x %.2f %.2f %.2f %.2f of "
                "the pixel sums, by %d batches)\n", v1, v2, v3, v4, kVbBatches);
    vb_print("GGX lamps (the file), depth 7 (the file's)", ggx7);
    vb_print("GGX lamps (the file), depth 6 (Tungsten's)", ggx6);
    vb_print("Beckmann lamps (Tungsten's), depth 7", beck7);
    vb_print("Beckmann lamps (Tungsten's), depth 6: the reference", beck6);
    const auto mean_within = [](const BlockComparison& c, double tol) {
        return std::abs(c.mean_ratio.x - 1.0) <= tol && std::abs(c.mean_ratio.y - 1.0) <= tol && std::abs(c.mean_ratio.z - 1.0) <= tol;
    };
    // Only both together match: the mean within 0.5 % per channel, the median block within 0.5 %
    // and at least 90 % of the 64 blocks within |z| < 3; every other combination misses by far.
    CHECK(mean_within(beck6, 0.005));
    CHECK(std::abs(beck6.median_relative_error) < 0.005);
    CHECK(beck6.share_within_3 >= 0.9);
    for (const BlockComparison* c : {&ggx7, &ggx6, &beck7}) {
        CHECK(std::abs(c->median_relative_error) > 0.006);
        CHECK(c->share_within_3 < 0.75);
    }
    CHECK(!mean_within(ggx6, 0.008));  // the depth alone leaves the image 1.1 % dark
    CHECK(!mean_within(beck7, 0.008));  // the lamps alone make it 1.4 % bright
}

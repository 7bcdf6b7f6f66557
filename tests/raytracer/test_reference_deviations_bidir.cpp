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

constexpr int kVbDepth = 7;    // the reference's (the conversion wrote Tungsten's 6 bounces as maxdepth 7)
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
VbRender vb_render(const Scene& s, int spp, std::uint64_t seed, int block) {
    const auto accel = make_accel(AccelKind::Bvh, s);
    std::vector<Image> batches;
    VbRender out{Image(s.film.width, s.film.height), Image(s.film.width, s.film.height)};
    const int per = spp / kVbBatches;
    for (int b = 0; b < kVbBatches; ++b) {
        RenderOptions o;
        o.spp = per;
        o.first_sample = b * per;
        o.max_depth = kVbDepth;
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
    std::printf("  %-44s mean %.4f %.4f %.4f, blocks |z|<3 %5.1f %% |z|<5 %5.1f %% (%zu), median block %+.2f %%\n", what,
                c.mean_ratio.x, c.mean_ratio.y, c.mean_ratio.z, 100.0 * c.share_within_3, 100.0 * c.share_within_5, c.tested,
                100.0 * c.median_relative_error);
}

}  // namespace

TEST_CASE("reference deviations: veach-bidir, our bdpt and our path tracer agree at the reference's depth", "[.][reference-deviations]") {
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

TEST_CASE("reference deviations: veach-bidir's lamps are Beckmann in Tungsten's form, GGX in the pbrt-v4 file, and that is not the deviation", "[.][reference-deviations]") {
    if (!vb_have()) return;
    // Tungsten's scene gives "Lamp" (the floor lamp's shade and stand, the table lamp) as
    // rough_conductor, distribution beckmann, roughness 0.25 (Tungsten's alpha); pbrt-v4's
    // conductor is Trowbridge-Reitz (GGX) only, and the file keeps alpha 0.25 with it. GGX's long
    // tails throw the light the shade reflects wide, which was the suspect for the pattern (ours
    // darker on the ceiling above the lamp, brighter elsewhere).
    constexpr int kBlock = 8;
    Scene s = vb_scene(64, IntegratorKind::Bdpt);
    const DownsampledReference ref = downsample_reference(read_image(vb_folder() / "TungstenRender.exr"), 1024 / 64);
    const VbRender ggx = vb_render(s, 1024, 21, kBlock);
    for (Material& m : s.materials)
        if (m.name == "Lamp") m.microfacet = Material::Microfacet::Beckmann;
    const VbRender beckmann = vb_render(s, 1024, 21, kBlock);
    const BlockComparison cg = compare_blocks(ggx.image, vb_scaled(ggx), ref.image, ref.variance, ref.valid, kBlock);
    const BlockComparison cb = compare_blocks(beckmann.image, vb_scaled(beckmann), ref.image, ref.variance, ref.valid, kBlock);
    std::printf("veach-bidir, 64 px, depth %d, bdpt 1024 spp against Tungsten's reference (block variance x %.2f, x %.2f)\n",
                kVbDepth, ggx.block_scale, beckmann.block_scale);
    vb_print("Lamp GGX alpha 0.25 (the pbrt-v4 file)", cg);
    vb_print("Lamp Beckmann alpha 0.25 (Tungsten's form)", cb);
    // A suspect ruled out: Beckmann's lamps move the image further from the reference, not closer
    // (measured: median block +2.2 % with GGX, +3.2 % with Beckmann, the mean 1 % brighter).
    CHECK(cg.median_relative_error > 0.01);
    CHECK(cb.median_relative_error > cg.median_relative_error);
    CHECK(cb.mean_ratio.y > cg.mean_ratio.y);
}

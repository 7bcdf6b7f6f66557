// The Cornell box against another renderer: Blender's Cycles, an independent path tracer, rendered
// the scene translated from scenes/cornell-box.json by tools/cycles-reference.sh (the command and
// its settings: reference_images/cycles/README.md). Both renderers use a 1-pixel box filter and
// unbounded depth (paths end by Russian roulette), so the two estimate the same pixel integrals
// and must agree within their noise everywhere, edges included: a z-test on 8x8 block means
// whose sigma counts both sides' noise. The mutation checks show the test can tell a small
// systematic error from noise.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "raytracer/accel/accel.hpp"
#include "raytracer/image/diff.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/scene.hpp"

using namespace sweeptrace;

namespace {

const std::filesystem::path source_dir = SWEEPTRACE_SOURCE_DIR;
constexpr int kSize = 128;        // the reference's size (reference_images/cycles/README.md)
constexpr int kMaxDepth = 1024;   // as Cycles' bounces: neither renderer truncates paths
constexpr int kSpp = 256;
constexpr std::uint64_t kSeed = 1;

struct CyclesReference {
    Image mean;      // mean of the Cycles runs
    Image variance;  // variance of that mean per pixel and channel, from the runs' spread
};

const CyclesReference& cycles_reference() {
    static const CyclesReference ref{
        read_image(source_dir / "reference_images" / "cycles" / "cornell-box-mean.pfm"),
        read_image(source_dir / "reference_images" / "cycles" / "cornell-box-variance.pfm")};
    return ref;
}

Scene cornell_box() {
    Scene scene = load_scene(source_dir / "scenes" / "cornell-box.json");
    scene.film.width = kSize;
    scene.film.height = kSize;
    return scene;
}

// Independent samples: their variance / spp is the variance of the pixel mean exactly (Sobol's
// estimate would overstate it and make the test lenient).
RenderResult render_ours(const Scene& scene, AccelKind accel, int max_depth = kMaxDepth) {
    const auto structure = make_accel(accel, scene);
    RenderOptions options;
    options.spp = kSpp;
    options.max_depth = max_depth;
    options.seed = kSeed;
    options.sampler = SamplerKind::Independent;
    return render(scene, *structure, options);
}

BlockTestResult compare_to_cycles(const RenderResult& ours) {
    const CyclesReference& ref = cycles_reference();
    REQUIRE(ref.mean.width == ours.image.width);
    REQUIRE(ref.mean.height == ours.image.height);
    // Var(ours - cycles) = Var(ours) + Var(cycles): the two are independent estimates.
    Image variance = ours.variance;
    for (std::size_t i = 0; i < variance.pixels.size(); ++i) variance.pixels[i] += ref.variance.pixels[i];
    BlockTestOptions options;
    options.block = 8;
    options.golden_is_8bit = false;
    options.false_alarm = 1e-4;
    return block_test(ref.mean, ours.image, variance, options);
}

std::size_t object_named(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].name == name) return i;
    FAIL("scene has no object named " << name);
    return 0;
}

void expect_agreement(AccelKind accel, const char* name) {
    const RenderResult ours = render_ours(cornell_box(), accel);
    REQUIRE(ours.stats.nonfinite_samples == 0);
    const BlockTestResult r = compare_to_cycles(ours);
    INFO(r.summary());
    CHECK(r.pass());
    WARN("cornell-box vs Cycles, " << name << ": " << r.summary());
}

void expect_rejected(const RenderResult& ours, const char* label) {
    const BlockTestResult r = compare_to_cycles(ours);
    INFO(r.summary());
    CHECK_FALSE(r.pass());
    WARN(label << ": " << r.summary());
}

}  // namespace

TEST_CASE("cornell box agrees with Cycles' reference, bvh", "[image][cycles]") {
    expect_agreement(AccelKind::Bvh, "bvh");
}

TEST_CASE("cornell box agrees with Cycles' reference, embree", "[image][cycles]") {
    expect_agreement(AccelKind::Embree, "embree");
}

TEST_CASE("cornell box vs Cycles: white walls 3% darker are rejected", "[image][cycles][mutation]") {
    Scene scene = cornell_box();
    Material& white = scene.materials[scene.objects[object_named(scene, "back wall")].material];
    white.albedo *= 0.97f;
    expect_rejected(render_ours(scene, AccelKind::Bvh), "white albedo x0.97");
}

TEST_CASE("cornell box vs Cycles: paths cut at the scene's depth 8 are rejected", "[image][cycles][mutation]") {
    // scenes/cornell-box.json renders with max_depth 8: the light of longer paths is missing.
    expect_rejected(render_ours(cornell_box(), AccelKind::Bvh, 8), "max depth 8");
}

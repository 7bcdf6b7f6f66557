// Vertex connection and merging (render/integrators/vcm.hpp): it converges to the path tracer's
// image (block z-test) on shipped scenes; its MIS weights sum to 1 over the connections and
// merges of random paths and a planted wrong weight does not; the radius follows the progressive
// schedule; the image is the same bit for bit on 1 and 3 threads and split into farm parts
// (iteration i is sample index i, its radius and light pass depend on nothing else).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <random>

#include "convergence_harness.hpp"
#include "raytracer/render/integrators/vcm.hpp"
#include "raytracer/render/integrators/vcm_mis.hpp"
#include "raytracer/render/planted_defect.hpp"
#include "raytracer/scene/load_scene.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

Scene vcm_shipped(const char* name, int width, int height) {
    Scene s = load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / name);
    s.film.width = width;
    s.film.height = height;
    s.film.clamp_indirect = 0.0f;  // the path tracer's biased firefly guard: off, as for bdpt's test
    return s;
}

RenderResult vcm_render(const Scene& scene, const Accel& accel, IntegratorKind integrator, int spp, std::uint64_t seed,
                        int threads = 0, int first_sample = 0, PlantedDefect defect = PlantedDefect::None) {
    RenderOptions o;
    o.integrator = integrator;
    o.spp = spp;
    o.first_sample = first_sample;
    o.max_depth = scene.film.max_depth;
    o.seed = seed;
    o.threads = threads;
    return render_with_planted_defect(scene, accel, o, defect);
}

// As bdpt's test: both renders noisy, the reference's noise counted as large again.
BlockTestResult vcm_against(const RenderResult& reference, const RenderResult& r, int block) {
    BlockTestOptions options;
    options.block = block;
    options.golden_is_8bit = false;
    options.reference_noise_ratio = 1.0;
    options.null_variance = &reference.variance;
    return block_test(reference.image, r.image, r.variance, options);
}

}  // namespace

TEST_CASE("vcm: converges to the path tracer's image on cornell-box and default", "[vcm][convergence]") {
    for (const auto& [name, w, h] : {std::tuple{"cornell-box.json", 24, 24}, std::tuple{"default.json", 32, 18}}) {
        INFO(name);
        const Scene scene = vcm_shipped(name, w, h);
        const auto accel = make_accel(AccelKind::Bvh, scene);
        const RenderResult path = vcm_render(scene, *accel, IntegratorKind::Path, 256, 1);
        const RenderResult vcm = vcm_render(scene, *accel, IntegratorKind::Vcm, 128, 2);
        const BlockTestResult t = vcm_against(path, vcm, 4);
        INFO(t.summary());
        CHECK(t.pass());
        CHECK(vcm.stats.nonfinite_samples == 0);
    }
}

// Random paths as bdpt's MIS test draws them, with a merging density eta over four decades: over
// the connection strategies and the merges, the weights sum to 1; leaving the merges out of the
// connections' sums (the planted defect) makes them sum to more wherever a merge counted.
TEST_CASE("vcm: MIS weights sum to 1 over connections and merges of random paths, and a planted wrong weight does not",
          "[vcm][mis]") {
    std::mt19937 rng(4242);
    std::uniform_real_distribution<float> decade(-2.0f, 2.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int planted_over = 0, tested = 0, merged = 0;
    for (int n = 0; n < 2000; ++n) {
        MisPath p;
        p.k = 1 + static_cast<int>(unit(rng) * 8.0f);
        const auto size = static_cast<std::size_t>(p.k + 1);
        p.fwd.resize(size);
        p.rev.resize(size);
        p.delta.assign(size, 0);
        for (std::size_t i = 0; i < size; ++i) {
            p.fwd[i] = std::pow(10.0f, decade(rng));
            p.rev[i] = std::pow(10.0f, decade(rng));
        }
        for (int i = 1; i < p.k; ++i)
            if (unit(rng) < 0.25f) {
                p.delta[static_cast<std::size_t>(i)] = 1;
                p.fwd[static_cast<std::size_t>(i + 1)] = 0.0f;
                p.rev[static_cast<std::size_t>(i - 1)] = 0.0f;
            }
        p.nee0 = std::pow(10.0f, decade(rng));
        p.light_hittable = unit(rng) < 0.7f;
        p.light_to_camera = unit(rng) < 0.7f;
        const float eta = std::pow(10.0f, decade(rng));
        double sum = 0.0, planted = 0.0, merges = 0.0;
        int possible = 0;
        for (int s = 0; s <= p.k; ++s) {
            for (const bool merge : {false, true}) {
                const float w = vcm_mis_weight(p, s, merge, eta);
                REQUIRE(w >= 0.0f);
                REQUIRE(w <= 1.0f + 1e-6f);
                possible += w > 0.0f ? 1 : 0;
                sum += w;
                if (merge) merges += w;
                planted += vcm_mis_weight(p, s, merge, eta, true);
            }
            // Without merging, the weights are bdpt's.
            CHECK(vcm_mis_weight(p, s, false, 0.0f) == Approx(bdpt_mis_weight(p, s)).epsilon(1e-5));
            CHECK(vcm_mis_weight(p, s, true, 0.0f) == 0.0f);
        }
        INFO("path " << n << ", k " << p.k << ", eta " << eta);
        if (possible == 0) continue;
        ++tested;
        CHECK(sum == Approx(1.0).epsilon(1e-5));
        merged += merges > 1e-3 ? 1 : 0;
        if (merges > 1e-3 && merges < 1.0 - 1e-3) planted_over += planted > 1.0 + 1e-4 ? 1 : 0;
    }
    CHECK(tested > 1000);
    CHECK(merged > 300);
    CHECK(planted_over > 200);
}

TEST_CASE("vcm: the radius follows r_i = r_1 i^((alpha - 1) / 2), r_1 a fraction of the scene or film.vcm_radius",
          "[vcm]") {
    Scene scene = vcm_shipped("cornell-box.json", 8, 8);
    const LightSet lights(scene);
    const CameraModel camera(scene.camera, 8, 8);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    BdptIntegrator bdpt(scene, *accel, lights, camera, 5, PlantedDefect::None);
    const collision::Bounds3 world = scene_world_bounds(scene);
    const float r1 = VcmIntegrator::kDefaultRadiusFraction * 0.5f * glm::length(world.hi - world.lo);
    CHECK(VcmIntegrator::first_radius(scene) == Approx(r1));
    const VcmIntegrator vcm(scene, lights, bdpt, 5);
    CHECK(vcm.radius(0) == Approx(r1));
    CHECK(vcm.radius(9) == Approx(r1 * std::pow(10.0f, -0.125f)));
    CHECK(vcm.radius(99) == Approx(r1 * std::pow(100.0f, -0.125f)));
    scene.film.vcm_radius = 0.5f;
    CHECK(VcmIntegrator::first_radius(scene) == 0.5f);
}

TEST_CASE("vcm: the same image bit for bit on 1, 2 and 3 threads, and split into farm parts", "[vcm][determinism]") {
    Scene scene = vcm_shipped("default.json", 24, 14);
    scene.film.max_depth = 5;
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult one = vcm_render(scene, *accel, IntegratorKind::Vcm, 3, 9, 1);
    const RenderResult two = vcm_render(scene, *accel, IntegratorKind::Vcm, 3, 9, 2);
    const RenderResult three = vcm_render(scene, *accel, IntegratorKind::Vcm, 3, 9, 3);
    CHECK(same_bits(one.image, two.image));
    CHECK(one.sums == two.sums);
    CHECK(same_bits(one.image, three.image));
    CHECK(one.sums == three.sums);
    const RenderResult a = vcm_render(scene, *accel, IntegratorKind::Vcm, 1, 9, 2, 0);
    const RenderResult b = vcm_render(scene, *accel, IntegratorKind::Vcm, 2, 9, 2, 1);
    std::vector<PixelSum> merged = a.sums;
    for (std::size_t i = 0; i < merged.size(); ++i) merged[i] += b.sums[i];
    CHECK(merged == one.sums);
    // Not trivially equal: the merges reach the image (bdpt draws the same numbers for the rest).
    const RenderResult bdpt = vcm_render(scene, *accel, IntegratorKind::Bdpt, 3, 9, 1);
    CHECK_FALSE(same_bits(bdpt.image, one.image));
}

// scenes/caustic.json's floor under the water is lit through two refractions: light tracing and
// merging are its only techniques there. Seen from close by, looking down at it (no specular
// surface in view: what bdpt renders without light it cannot find), with a radius above the
// pixel footprint, merging carries most of the weight, so vcm must agree with bdpt, and leaving the
// merges out of the connections' weights (the planted defect) counts the caustic up to twice.
TEST_CASE("vcm: the caustic agrees with bdpt's, and a planted wrong weight does not", "[vcm][convergence]") {
    Scene scene = vcm_shipped("caustic.json", 32, 20);
    scene.camera.position = {0.0f, 0.4f, -0.3f};
    scene.camera.look_at = {0.0f, 0.0f, 0.3f};
    scene.film.vcm_radius = 0.02f;
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult bdpt = vcm_render(scene, *accel, IntegratorKind::Bdpt, 1024, 1);
    const RenderResult vcm = vcm_render(scene, *accel, IntegratorKind::Vcm, 512, 2);
    const BlockTestResult t = vcm_against(bdpt, vcm, 8);
    INFO(t.summary());
    CHECK(t.pass());
    const RenderResult wrong = vcm_render(scene, *accel, IntegratorKind::Vcm, 512, 2, 0, 0, PlantedDefect::VcmDropsMerges);
    const BlockTestResult w = vcm_against(bdpt, wrong, 8);
    INFO(w.summary());
    CHECK_FALSE(w.pass());
}

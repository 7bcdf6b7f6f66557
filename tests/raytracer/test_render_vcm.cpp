// Vertex connection and merging (render/integrators/vcm.hpp): it converges to the path tracer's
// image (block z-test) on shipped scenes; its MIS weights sum to 1 over the connections and
// merges of random paths and a planted wrong weight does not; the radius follows the progressive
// schedule; the image is the same bit for bit on 1 and 3 threads and split into farm parts
// (iteration i is sample index i, its radius and light pass depend on nothing else).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"
#include "random_mis_path.hpp"
#include "raytracer/render/integrators/vcm.hpp"
#include "raytracer/render/integrators/bidir_mis.hpp"
#include "raytracer/render/planted_defect.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// r against the reference by the block z-test (against_path): it must pass (`agrees`) or fail.
void vcm_expect(const RenderResult& reference, const RenderResult& r, int block, bool agrees) {
    const BlockTestResult t = against_path(reference, r, block);
    INFO(t.summary());
    CHECK(t.pass() == agrees);
}

}  // namespace

TEST_CASE("vcm: converges to the path tracer's image on cornell-box and default", "[vcm][convergence]") {
    for (const auto& [name, w, h] : {std::tuple{"cornell-box.json", 24, 24}, std::tuple{"default.json", 32, 18}}) {
        INFO(name);
        const Scene scene = shipped(name, w, h);
        const auto accel = make_accel(AccelKind::Bvh, scene);
        const RenderResult path = render_as(scene, *accel, IntegratorKind::Path, 256, 1);
        const RenderResult vcm = render_as(scene, *accel, IntegratorKind::Vcm, 128, 2);
        vcm_expect(path, vcm, 4, true);
        CHECK(vcm.stats.nonfinite_samples == 0);
    }
}

// Random paths as bdpt's MIS test draws them (random_mis_path.hpp), with a merging density eta
// over four decades: over the connection strategies and the merges, the weights sum to 1; leaving
// the merges out of the connections' sums (the planted defect) makes them sum to more wherever a
// merge counted. At a medium vertex there is no merge (weight 0, absent from the sums): a merge
// there weighted as if it were a technique would make the sums exceed 1.
TEST_CASE("vcm: MIS weights sum to 1 over connections and merges of random paths, and a planted wrong weight does not",
          "[vcm][mis]") {
    std::mt19937 rng(4242);
    std::uniform_real_distribution<float> decade(-2.0f, 2.0f);
    int planted_over = 0, tested = 0, merged = 0, medium_over = 0;
    for (int n = 0; n < 2000; ++n) {
        const MisPath p = random_mis_path(rng);
        const float eta = std::pow(10.0f, decade(rng));
        double sum = 0.0, planted = 0.0, merges = 0.0;
        int possible = 0;
        for (int s = 0; s <= p.k; ++s) {
            for (const bool merge : {false, true}) {
                const float w = mis_weight(p, s, merge, eta);
                REQUIRE(w >= 0.0f);
                REQUIRE(w <= 1.0f + 1e-6f);
                possible += w > 0.0f ? 1 : 0;
                sum += w;
                if (merge) merges += w;
                planted += mis_weight(p, s, merge, eta, MisDefect::DropMerges);
            }
            CHECK(mis_weight(p, s, true, 0.0f) == 0.0f);  // without merging, no merge has weight
        }
        INFO("path " << n << ", k " << p.k << ", eta " << eta);
        if (possible == 0) continue;
        ++tested;
        CHECK(sum == Approx(1.0).epsilon(1e-5));
        merged += merges > 1e-3 ? 1 : 0;
        if (merges > 1e-3 && merges < 1.0 - 1e-3) planted_over += planted > 1.0 + 1e-4 ? 1 : 0;
        for (int i = 1; i < p.k; ++i) {
            if (!p.medium(i)) continue;
            CHECK(mis_weight(p, i, true, eta) == 0.0f);
            MisPath as_surface = p;  // the merge's own weight as if it were one of the techniques
            as_surface.medium(i) = 0;
            const float extra = mis_weight(as_surface, i, true, eta);
            if (extra > 1e-3f) medium_over += sum + extra > 1.0 + 1e-4 ? 1 : 0;
        }
    }
    CHECK(tested > 1000);
    CHECK(merged > 300);
    CHECK(planted_over > 200);
    CHECK(medium_over > 100);
}

TEST_CASE("vcm: the radius follows r_i = r_1 i^((alpha - 1) / 2), r_1 half a pixel's footprint or film.vcm_radius",
          "[vcm]") {
    // A wall 2 units before a 90-degree pinhole, 16 pixels across: a pixel covers 2 x 2 tan(45) /
    // 16 = 0.25 of the wall along it, and across its ray 0.25 cos^2 of its angle off the axis, the
    // corners' 0.25 x 0.6 at least; the median centre ray's lies between.
    Scene wall;
    wall.film.width = wall.film.height = 16;
    wall.camera.position = {0.0f, 0.0f, 0.0f};
    wall.camera.look_at = {0.0f, 0.0f, -1.0f};
    wall.camera.vfov_degrees = 90.0f;
    wall.materials.push_back(Material{});
    Object quad;
    quad.shape = collision::Quad{{-10.0f, -10.0f, -2.0f}, {20.0f, 0.0f, 0.0f}, {0.0f, 20.0f, 0.0f}};
    wall.objects.push_back(quad);
    {
        const CameraModel camera(wall.camera, 16, 16);
        const auto accel = make_accel(AccelKind::Bvh, wall);
        const float footprint = VcmIntegrator::median_pixel_footprint(wall, *accel, camera);
        CHECK(footprint > 0.25f * 0.6f);
        CHECK(footprint <= 0.25f * 1.001f);
        CHECK(VcmIntegrator::first_radius(wall, *accel, camera) == Approx(0.5f * footprint));
        wall.film.vcm_radius = 0.5f;
        CHECK(VcmIntegrator::first_radius(wall, *accel, camera) == 0.5f);
    }
    // smallpt's walls are spheres of radius 1e5: a fraction of the scene's bounding sphere (the
    // rule before this one) made r_1 about 300 units in a room 100 wide, and vcm's image a blur.
    // Half a pixel's footprint at 24 pixels across a room 100 wide is about 2.
    {
        const Scene smallpt = shipped("smallpt.json", 24, 18);
        const CameraModel camera(smallpt.camera, 24, 18);
        const auto accel = make_accel(AccelKind::Bvh, smallpt);
        const float r1 = VcmIntegrator::first_radius(smallpt, *accel, camera);
        CHECK(r1 > 0.5f);
        CHECK(r1 < 5.0f);
    }
    Scene scene = shipped("cornell-box.json", 8, 8);
    const LightSet lights(scene);
    const CameraModel camera(scene.camera, 8, 8);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    BdptIntegrator bdpt(scene, *accel, lights, camera, 5, PlantedDefect::None);
    const VcmIntegrator vcm(scene, *accel, camera, bdpt, 5);
    const float r1 = VcmIntegrator::first_radius(scene, *accel, camera);
    CHECK(vcm.radius(0) == Approx(r1));
    CHECK(vcm.radius(9) == Approx(r1 * std::pow(10.0f, -0.125f)));
    CHECK(vcm.radius(99) == Approx(r1 * std::pow(100.0f, -0.125f)));
}

TEST_CASE("vcm: the same image bit for bit on 1, 2 and 3 threads, and split into farm parts, with every kind of light", "[vcm][determinism]") {
    const Scene scene = every_light_scene();
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult one = check_bit_identical(scene, *accel, IntegratorKind::Vcm);
    // Not trivially equal: the merges reach the image (bdpt draws the same numbers for the rest).
    const RenderResult bdpt = render_as(scene, *accel, IntegratorKind::Bdpt, 3, 9, PlantedDefect::None, 1);
    CHECK_FALSE(same_bits(bdpt.image, one.image));
}

// scenes/caustic.json's floor under the water is lit through two refractions: light tracing and
// merging are its only techniques there. Seen from close by, looking down at it (no specular
// surface in view: what bdpt renders without light it cannot find), with a radius above the
// pixel footprint, merging carries most of the weight, so vcm must agree with bdpt, and leaving the
// merges out of the connections' weights (the planted defect) counts the caustic up to twice.
TEST_CASE("vcm: the caustic agrees with bdpt's, and a planted wrong weight does not", "[vcm][convergence]") {
    Scene scene = shipped("caustic.json", 32, 20);
    scene.camera.position = {0.0f, 0.4f, -0.3f};
    scene.camera.look_at = {0.0f, 0.0f, 0.3f};
    scene.film.vcm_radius = 0.02f;
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult bdpt = render_as(scene, *accel, IntegratorKind::Bdpt, 1024, 1);
    vcm_expect(bdpt, render_as(scene, *accel, IntegratorKind::Vcm, 512, 2), 8, true);
    vcm_expect(bdpt, render_as(scene, *accel, IntegratorKind::Vcm, 512, 2, PlantedDefect::VcmDropsMerges), 8, false);
}

// Under motion blur a photon carries its own pixel's shutter time, so merging is off (vcm.hpp):
// what is left are bdpt's connections with bdpt's weights, drawing bdpt's numbers, so the image
// is bdpt's bit for bit. This also shows vcm's connections are bdpt's, merging aside.
TEST_CASE("vcm: with a moving object under an open shutter, merging is off and the image is bdpt's", "[vcm]") {
    Scene scene = shipped("motion.json", 24, 16);
    REQUIRE(scene.camera.shutter);
    scene.film.max_depth = 5;
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult vcm = render_as(scene, *accel, IntegratorKind::Vcm, 2, 3);
    const RenderResult bdpt = render_as(scene, *accel, IntegratorKind::Bdpt, 2, 3);
    CHECK(same_bits(vcm.image, bdpt.image));
    CHECK(vcm.sums == bdpt.sums);
}

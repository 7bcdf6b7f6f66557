// bdpt and vcm with participating media (render/media/subpath_flight.hpp, integrators/bdpt.cpp):
// both agree with the path tracer (block z-test) on medium scenes with surfaces:
//   - a chromatic, anisotropic ball behind an interface surface over a floor, lit from outside;
//   - a quad light inside the ball's medium (no boundary of its own: the light subpath finds
//     its medium), a spot light inside it (its medium found once, bdpt.cpp's light_media) and
//     a point light in the camera's unbounded fog;
//   - the ball as a grid of constant density (the MIS weights' grid rule, subpath_flight.hpp);
// the native BVH and Embree agree under bdpt, and bdpt and vcm are bit-identical at any thread
// count and across a farm split. Media that emit (gathered by the camera subpath's flights,
// subpath_flight.hpp): an absorbing, emitting slab seen head-on against its closed form
// Le (1 - exp(-sigma_a d)) and a grid's Le grid against a quadrature, by all three integrators;
// an emitting, scattering ball lit by a quad light (homogeneous and grid) by bdpt and vcm
// against the path tracer; light tracing alone, which cannot see emission, refuses it.
#include <catch2/catch.hpp>

#include "bidirectional_test_support.hpp"
#include "media_test_scenes.hpp"
#include "raytracer/input_error.hpp"

using namespace sweeptrace;
using sweeptrace::testing::check_bidirectional_agree_with_path;
using sweeptrace::testing::homogeneous_medium;
using sweeptrace::testing::medium_ball_scene;

namespace {

Medium chromatic() { return homogeneous_medium({0.1f, 0.2f, 0.4f}, {1.2f, 0.9f, 0.6f}, 0.3f); }

Scene ball(const Medium& m) {
    Scene s = medium_ball_scene(m);
    s.film.max_depth = 6;
    s.film.clamp_indirect = 0.0f;  // the path tracer's guard is biased on purpose; bdpt's estimate is not clamped
    return s;
}

}  // namespace

TEST_CASE("media bidir: bdpt and vcm agree with the path tracer on a medium ball over a floor", "[media][bdpt][vcm]") {
    const Scene scene = ball(chromatic());
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
    // The test can fail here: next event estimation left out of the weights' sums (from medium
    // vertices too) counts direct light up to twice.
    const RenderResult path = sweeptrace::testing::render_as(scene, *accel, IntegratorKind::Path, 512, 1);
    const RenderResult wrong =
        sweeptrace::testing::render_as(scene, *accel, IntegratorKind::Bdpt, 128, 2, PlantedDefect::BdptDropsNee);
    const BlockTestResult w = sweeptrace::testing::against_path(path, wrong, 4);
    INFO(w.summary());
    CHECK_FALSE(w.pass());
}

TEST_CASE("media bidir: a light inside the medium, and a point light in the camera's fog", "[media][bdpt][vcm]") {
    SECTION("a quad light inside the ball") {
        Scene scene = ball(homogeneous_medium(glm::vec3(0.05f), glm::vec3(0.8f), -0.2f));
        Object& lamp = scene.objects.back();  // medium_ball_scene's lamp, moved into the ball
        lamp.shape = collision::Quad{glm::vec3(-0.3f, 0.3f, -0.3f), glm::vec3(0.6f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 0.6f)};
        scene.materials[lamp.material].two_sided_emission = true;
        const auto accel = make_accel(AccelKind::Bvh, scene);
        check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
    }
    SECTION("a spot light inside the ball (its medium found once, at setup)") {
        // Turned down, away from the camera: bdpt and vcm would see a point light's own dot in
        // the image (light tracing, t = 1), which the path tracer never finds.
        Scene scene = ball(homogeneous_medium(glm::vec3(0.05f), glm::vec3(0.8f), 0.3f));
        scene.objects.pop_back();  // no quad light
        SceneLight spot;
        spot.type = SceneLight::Type::Spot;
        spot.position = {0.2f, 0.3f, -0.1f};
        spot.direction = {0.0f, -1.0f, 0.0f};
        spot.cos_cone = std::cos(0.7f);
        spot.cos_falloff_start = std::cos(0.5f);
        spot.intensity = glm::vec3(6.0f);
        scene.lights.push_back(spot);
        const auto accel = make_accel(AccelKind::Bvh, scene);
        check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
    }
    SECTION("a point light in unbounded fog") {
        Scene scene = ball(homogeneous_medium(glm::vec3(0.02f), glm::vec3(0.15f), 0.5f));
        scene.camera.medium = 1;
        scene.media.push_back(homogeneous_medium(glm::vec3(0.01f), glm::vec3(0.1f), 0.2f));
        scene.objects.front().media.outside = 1;  // the ball's outside is the fog
        scene.objects.pop_back();                 // no quad light
        SceneLight point;
        point.type = SceneLight::Type::Point;
        point.position = {0.5f, 1.8f, 0.5f};
        point.intensity = glm::vec3(4.0f);
        scene.lights.push_back(point);
        const auto accel = make_accel(AccelKind::Bvh, scene);
        check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
    }
}

TEST_CASE("media bidir: bdpt and vcm agree with the path tracer on a grid medium", "[media][bdpt][vcm]") {
    const Scene scene = ball(sweeptrace::testing::constant_grid(chromatic(), 2.0f));
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
}

TEST_CASE("media bidir: the BVH and Embree agree under bdpt, and any thread count and a farm split are bit-identical",
          "[media][bdpt][vcm]") {
    const Scene scene = ball(chromatic());
    const auto bvh = make_accel(AccelKind::Bvh, scene);
    const auto embree = make_accel(AccelKind::Embree, scene);
    const RenderResult a = sweeptrace::testing::render_as(scene, *bvh, IntegratorKind::Bdpt, 64, 3);
    const RenderResult b = sweeptrace::testing::render_as(scene, *embree, IntegratorKind::Bdpt, 64, 4);
    CHECK(sweeptrace::testing::blocks_apart(a, b) == 0);
    for (const IntegratorKind k : {IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        INFO((k == IntegratorKind::Vcm ? "vcm" : "bdpt"));
        const RenderResult one = sweeptrace::testing::check_bit_identical(scene, *bvh, k);
        CHECK(one.stats.nonfinite_samples == 0);
    }
}

namespace {

// The camera at the origin looking down -z through one pixel of a tiny field of view (the pixel
// is the radiance along one ray) at an interface box holding medium 0 between z = -1 and -2,
// wide in x and y, nothing behind it.
Scene slab_scene(const Medium& m) {
    Scene scene = sweeptrace::testing::empty_scene(1, 1);
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.look_at = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.vfov_degrees = 1e-3f;
    scene.media.push_back(m);
    Material boundary;
    boundary.type = Material::Type::Interface;
    sweeptrace::testing::add_object(scene, collision::Aabb{glm::vec3(0.0f, 0.0f, -1.5f), glm::vec3(8.0f, 8.0f, 1.0f)},
                                    sweeptrace::test::add_material(scene, boundary), glm::mat4(1.0f), "slab");
    scene.objects.back().media.inside = 0;
    return scene;
}

// Each integrator's pixel within its noise of `truth`, the noise small against it.
void check_pixel(const Scene& scene, const glm::dvec3& truth) {
    const auto accel = make_accel(AccelKind::Bvh, scene);
    for (const IntegratorKind k : {IntegratorKind::Path, IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        const RenderResult r = sweeptrace::testing::render_as(scene, *accel, k, 16384, 5);
        for (int c = 0; c < 3; ++c) {
            const double e = r.image.at(0, 0)[c], se = std::sqrt(static_cast<double>(r.variance.at(0, 0)[c]));
            INFO(integrator_name(k) << ", channel " << c << ": render " << e << " +- " << se << ", truth " << truth[c]);
            CHECK(std::abs(e - truth[c]) <= sweeptrace::test::z_bound(9) * se + 1e-5 * truth[c]);
            CHECK(se < 0.02 * truth[c]);  // teeth: half the emission, or none, is many deviations away
        }
    }
}

Medium glowing(const Medium& m, const glm::vec3& le) {
    Medium out = m;
    out.emission = le;
    return out;
}

}  // namespace

TEST_CASE("media bidir: an absorbing, emitting slab seen head-on gives Le (1 - exp(-sigma_a d))", "[media][bdpt][vcm]") {
    const glm::dvec3 sa(0.5, 1.0, 2.0), le(1.0, 2.0, 0.5);
    Scene scene = slab_scene(glowing(homogeneous_medium(glm::vec3(sa), glm::vec3(0.0f)), glm::vec3(le)));
    scene.film.max_depth = 3;
    glm::dvec3 truth;
    for (int c = 0; c < 3; ++c) truth[c] = le[c] * (1.0 - std::exp(-sa[c] * 1.0));
    check_pixel(scene, truth);
}

TEST_CASE("media bidir: a grid's Le grid, seen through an absorbing slab, against a quadrature", "[media][bdpt][vcm]") {
    // Density 1 everywhere, the emission's scale in four layers along z (voxel centres at z =
    // -2.25, -1.75, -1.25, -0.75), 3 x 3 in x and y so that the ray (x = y = 0) runs through the
    // middle voxels' centres: along it Le is the layers' linear interpolation.
    const glm::dvec3 sa(0.5, 1.0, 2.0), le(1.0, 2.0, 0.5);
    const double layers[4] = {0.5, 2.0, 1.0, 3.0};
    Medium m = glowing(homogeneous_medium(glm::vec3(sa), glm::vec3(0.0f)), glm::vec3(le));
    m.kind = Medium::Kind::Grid;
    m.nx = m.ny = 3;
    m.nz = 4;
    m.density.assign(36, 1.0f);
    for (int z = 0; z < 4; ++z)
        for (int i = 0; i < 9; ++i) m.emission_scale.push_back(static_cast<float>(layers[z]));
    m.p0 = glm::vec3(-5.0f, -5.0f, -2.5f);
    m.p1 = glm::vec3(5.0f, 5.0f, -0.5f);
    Scene scene = slab_scene(m);
    scene.film.max_depth = 3;
    // L = integral over t in [1, 2] (z = -t) of exp(-sigma_a (t - 1)) sigma_a Le s(z), Simpson.
    const auto scale = [&](double z) {
        const double u = (z + 2.25) / 0.5;  // layer index coordinate
        const int k = std::min(2, static_cast<int>(std::floor(u)));
        return layers[k] + (u - k) * (layers[k + 1] - layers[k]);
    };
    glm::dvec3 truth(0.0);
    const int n = 20000;
    for (int i = 0; i <= n; ++i) {
        const double t = 1.0 + static_cast<double>(i) / n;
        const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        for (int c = 0; c < 3; ++c) truth[c] += w / (3.0 * n) * std::exp(-sa[c] * (t - 1.0)) * sa[c] * le[c] * scale(-t);
    }
    check_pixel(scene, truth);
}

TEST_CASE("media bidir: bdpt and vcm agree with the path tracer on an emitting, scattering medium under a light",
          "[media][bdpt][vcm]") {
    const Medium h = glowing(chromatic(), {2.0f, 1.0f, 0.5f});
    SECTION("homogeneous") {
        const Scene scene = ball(h);
        const auto accel = make_accel(AccelKind::Bvh, scene);
        check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
        // The test can fail here: the same medium without its emission is told apart.
        const RenderResult path = sweeptrace::testing::render_as(scene, *accel, IntegratorKind::Path, 512, 1);
        const Scene dark = ball(chromatic());
        const auto dark_accel = make_accel(AccelKind::Bvh, dark);
        const RenderResult wrong = sweeptrace::testing::render_as(dark, *dark_accel, IntegratorKind::Bdpt, 128, 2);
        const BlockTestResult w = sweeptrace::testing::against_path(path, wrong, 4);
        INFO(w.summary());
        CHECK_FALSE(w.pass());
    }
    SECTION("a grid with an Le grid") {
        Medium g = sweeptrace::testing::constant_grid(h, 2.0f);
        for (int i = 0; i < 64; ++i) g.emission_scale.push_back(0.25f * static_cast<float>(i % 7));
        const Scene scene = ball(g);
        const auto accel = make_accel(AccelKind::Bvh, scene);
        check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
    }
}

TEST_CASE("media bidir: light tracing alone refuses a medium that emits, which only camera subpaths find",
          "[media][bdpt]") {
    const Scene scene = ball(glowing(chromatic(), glm::vec3(1.0f)));
    const auto accel = make_accel(AccelKind::Bvh, scene);
    RenderOptions o;
    o.spp = 1;
    o.integrator = IntegratorKind::Bdpt;
    o.sampling = Sampling::LightTracing;
    CHECK_THROWS_AS(render(scene, *accel, o), InputError);
    CHECK_THROWS_WITH(render(scene, *accel, o), Catch::Contains("light tracing alone does not render a medium's emission"));
    const Scene plain = ball(chromatic());
    const auto plain_accel = make_accel(AccelKind::Bvh, plain);
    CHECK_NOTHROW(render(plain, *plain_accel, o));
}

// Bidirectional path tracing (render/integrators/bdpt.hpp): it converges to the path tracer's
// image (block z-test) on shipped scenes, and a planted wrong MIS weight does not; light tracing
// alone (t = 1) matches the closed form of a small Lambertian emitter over a diffuse plane; the
// MIS weights sum to 1 over the strategies of random paths; the image is the same bit for bit on
// 1, 2 and 3 threads and split into farm parts, also when a pass's splats are added in waves
// (bdpt and vcm); the emission and camera densities are the ones
// sampled with.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <random>

#include <glm/geometric.hpp>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"
#include "random_mis_path.hpp"
#include "raytracer/render/camera.hpp"
#include "raytracer/render/integrators/bidir_mis.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/planted_defect.hpp"
#include "raytracer/scene/load_scene.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// 128 spp of bdpt against 256 of path, 4x4 blocks; returns the path render.
RenderResult check_converges_to_path(const Scene& scene, const Accel& accel) {
    RenderResult path = render_as(scene, accel, IntegratorKind::Path, 256, 1);
    const RenderResult bdpt = render_as(scene, accel, IntegratorKind::Bdpt, 128, 2);
    const BlockTestResult t = against_path(path, bdpt, 4);
    INFO(t.summary());
    CHECK(t.pass());
    CHECK(bdpt.stats.nonfinite_samples == 0);
    return path;
}

}  // namespace

TEST_CASE("bdpt: converges to the path tracer's image on cornell-box, and a planted wrong MIS weight does not",
          "[bdpt][convergence]") {
    const Scene scene = shipped("cornell-box.json", 24, 24);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult path = check_converges_to_path(scene, *accel);
    // Next event estimation left out of the weights' sums: direct light counted up to twice.
    const RenderResult wrong = render_as(scene, *accel, IntegratorKind::Bdpt, 128, 2, PlantedDefect::BdptDropsNee);
    const BlockTestResult w = against_path(path, wrong, 4);
    INFO(w.summary());
    CHECK_FALSE(w.pass());
}

TEST_CASE("bdpt: converges to the path tracer's image on default (thin lens, sphere light, glass, a mesh)",
          "[bdpt][convergence]") {
    const Scene scene = shipped("default.json", 32, 18);
    check_converges_to_path(scene, *make_accel(AccelKind::Bvh, scene));
}

// A square emitter of side a and radiance Le at height h, facing down, outside the view of a
// camera looking straight down at a diffuse plane of albedo rho: the plane's radiance is
// rho / pi times the irradiance int Le cos(theta) cos(theta') / r^2 dA (both cosines h / r),
// evaluated per pixel by a midpoint rule over the pixel (4 x 4) and the emitter (4 x 4).
TEST_CASE("bdpt: light tracing alone matches the closed form of a small emitter over a diffuse plane",
          "[bdpt][convergence]") {
    constexpr int kSize = 24;
    constexpr float kRho = 0.5f, kLe = 500.0f, kSide = 0.1f, kHeight = 1.0f, kX = 3.0f;
    Scene scene = empty_scene(kSize, kSize);
    scene.camera.position = {0.0f, 4.0f, 0.0f};
    scene.camera.look_at = glm::vec3(0.0f);
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.vfov_degrees = 60.0f;
    scene.film.max_depth = 2;
    add_object(scene, collision::Quad{{-50.0f, 0.0f, -50.0f}, {0.0f, 0.0f, 100.0f}, {100.0f, 0.0f, 0.0f}},
               add_material(scene, diffuse(kRho)), glm::mat4(1.0f), "plane");
    Material emitter;
    emitter.type = Material::Type::Emissive;
    emitter.emission = glm::vec3(kLe);
    const glm::vec3 corner(kX - 0.5f * kSide, kHeight, -0.5f * kSide);
    add_object(scene, collision::Quad{corner, {kSide, 0.0f, 0.0f}, {0.0f, 0.0f, kSide}},  // normal -y
               add_material(scene, emitter), glm::mat4(1.0f), "emitter");

    const CameraModel camera(scene.camera, kSize, kSize);
    Image truth(kSize, kSize);
    constexpr int kSub = 4;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            double sum = 0.0;
            for (int j = 0; j < kSub; ++j)
                for (int i = 0; i < kSub; ++i) {
                    const collision::Ray r = camera.generate(x + (i + 0.5f) / kSub, y + (j + 0.5f) / kSub, 0.5f, 0.5f);
                    const glm::dvec3 o(r.origin), d(r.dir);
                    const glm::dvec3 p = o + d * (-o.y / d.y);
                    double e = 0.0;
                    for (int v = 0; v < kSub; ++v)
                        for (int u = 0; u < kSub; ++u) {
                            const glm::dvec3 q = glm::dvec3(corner) + glm::dvec3((u + 0.5) / kSub * kSide, 0.0, (v + 0.5) / kSub * kSide);
                            const glm::dvec3 w = q - p;
                            const double r2 = glm::dot(w, w);
                            e += kLe * (kHeight * kHeight / (r2 * r2)) * (kSide * kSide / (kSub * kSub));
                        }
                    sum += kRho / 3.14159265358979323846 * e;
                }
            truth.at(x, y) = glm::vec3(static_cast<float>(sum / (kSub * kSub)));
        }
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult r = render_as(scene, *accel, IntegratorKind::Bdpt, 1024, 5, PlantedDefect::None, 0, 0,
                                     Sampling::LightTracing);
    // 1e-4: float rounding of the estimate and the midpoint rules' error (the emitter subtends
    // under 0.3 degrees per cell seen from the nearest pixel).
    const BlockTestResult t = test_against_truth(truth, r, 4, 1e-4, nullptr);
    INFO(t.summary());
    CHECK(t.pass());
    CHECK(t.blocks_tested == 36);
    // A wrong answer is caught: the same render against a truth 3% brighter.
    Image brighter = truth;
    for (glm::vec3& p : brighter.pixels) p *= 1.03f;
    CHECK_FALSE(test_against_truth(brighter, r, 4, 1e-4, nullptr).pass());
}

// Random paths (random_mis_path.hpp): over the possible strategies the weights sum to 1; leaving
// next event estimation out of the sums (the planted defect) makes them sum to more wherever it
// was possible.
TEST_CASE("bdpt: MIS weights sum to 1 over the strategies of random paths, and a planted wrong weight does not",
          "[bdpt][mis]") {
    std::mt19937 rng(12345);
    int planted_over = 0, tested = 0;
    for (int n = 0; n < 2000; ++n) {
        const MisPath p = random_mis_path(rng);
        double sum = 0.0, planted = 0.0;
        int possible = 0;
        for (int s = 0; s <= p.k; ++s) {
            const float w = mis_weight(p, s, false, 0.0f);
            REQUIRE(w >= 0.0f);
            REQUIRE(w <= 1.0f);
            possible += w > 0.0f ? 1 : 0;
            sum += w;
            planted += mis_weight(p, s, false, 0.0f, MisDefect::DropNee);
        }
        INFO("path " << n << ", k " << p.k);
        if (possible == 0) continue;  // every strategy blocked by delta vertices: no estimator at all
        ++tested;
        CHECK(sum == Approx(1.0).epsilon(1e-5));
        if (possible >= 2 && mis_weight(p, 1, false, 0.0f) > 1e-3f) planted_over += planted > 1.0 + 1e-4 ? 1 : 0;
    }
    CHECK(tested > 1000);
    CHECK(planted_over > 200);
}

TEST_CASE("bdpt: the same image bit for bit on 1, 2 and 3 threads, and split into farm parts", "[bdpt][determinism]") {
    const Scene scene = every_light_scene();
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult one = check_bit_identical(scene, *accel, IntegratorKind::Bdpt);
    // Not trivially equal: the light subpaths' splats reach the image.
    const RenderResult path = render_as(scene, *accel, IntegratorKind::Path, 3, 9, PlantedDefect::None, 1);
    CHECK_FALSE(same_bits(path.image, one.image));
}

TEST_CASE("bdpt and vcm: the same bits on 1, 2 and 3 threads and across farm parts when a pass's splats come in two waves",
          "[bdpt][vcm][determinism]") {
    // 65 tiles in a row (1040 x 2 pixels): the renderer adds the splats of tiles 0..63, then of
    // tile 64 (film_splats.hpp); a Gaussian of radius 2 spreads splats across the waves' border.
    Scene scene = every_light_scene();
    scene.film.width = 65 * 16;
    scene.film.height = 2;
    scene.film.filter.type = FilterSpec::Type::Gaussian;
    scene.film.filter.radius = 2.0f;
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult bdpt = check_bit_identical(scene, *accel, IntegratorKind::Bdpt);
    check_bit_identical(scene, *accel, IntegratorKind::Vcm);
    const RenderResult path = render_as(scene, *accel, IntegratorKind::Path, 3, 9, PlantedDefect::None, 1);
    CHECK_FALSE(same_bits(path.image, bdpt.image));
}

// What sample_emission draws and what emission_density says of the same point and direction
// agree, for every kind of light: the densities bdpt's MIS uses are the sampled ones.
TEST_CASE("bdpt: emission densities are the ones sample_emission draws with, for every kind of light", "[bdpt][lights]") {
    Scene scene = empty_scene(8, 8);
    Material lamp;
    lamp.type = Material::Type::Emissive;
    lamp.emission = glm::vec3(2.0f, 1.5f, 1.0f);
    const std::uint32_t one_sided = add_material(scene, lamp);
    lamp.two_sided_emission = true;
    const std::uint32_t two_sided = add_material(scene, lamp);
    add_object(scene, collision::Quad{{0.0f, 2.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}, two_sided,
               glm::mat4(1.0f), "panel");
    add_object(scene, collision::Sphere{{2.0f, 1.0f, 0.0f}, 0.5f}, one_sided, glm::mat4(1.0f), "ball");
    add_object(scene, collision::Sphere{{0.0f, 0.0f, 0.0f}, 1.0f}, one_sided,
               glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-2.0f, 1.0f, 0.0f)), glm::vec3(0.5f, 1.0f, 0.3f)),
               "ellipsoid");
    SceneLight point;
    point.type = SceneLight::Type::Point;
    point.intensity = glm::vec3(3.0f);
    SceneLight spot = point;
    spot.type = SceneLight::Type::Spot;
    spot.cos_cone = std::cos(0.6f);
    spot.cos_falloff_start = std::cos(0.4f);
    SceneLight sun;
    sun.type = SceneLight::Type::Directional;
    sun.irradiance = glm::vec3(1.0f);
    sun.half_angle = 0.1f;
    SceneLight directional = sun;
    directional.half_angle = 0.0f;
    scene.lights = {point, spot, sun, directional};
    const LightSet lights(scene);
    REQUIRE(lights.light_count() == 7);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 0.999f);
    std::vector<int> seen(lights.light_count(), 0);
    for (int n = 0; n < 4000; ++n) {
        LightEmission e;
        if (!lights.sample_emission(unit(rng), unit(rng), unit(rng), unit(rng), unit(rng), unit(rng), e)) continue;
        ++seen[e.light];
        const LightSet::EmissionDensity d = lights.emission_density(e.light, e.normal, e.dir);
        INFO("light " << e.light);
        CHECK(e.selection == Approx(lights.light_selection(e.light)));
        CHECK(d.pos == Approx(e.selection * (e.at_infinity ? e.pdf_dir : e.pdf_pos)).epsilon(1e-4));
        CHECK(d.dir == Approx(e.at_infinity ? e.pdf_pos : e.pdf_dir).epsilon(1e-4));
        if (!e.at_infinity && !e.delta_position) {
            // On the surface it claims, facing the side it emits from.
            CHECK(glm::length(e.normal) == Approx(1.0f).epsilon(1e-4));
            if (!scene.materials[scene.objects[e.object].material].two_sided_emission) CHECK(glm::dot(e.normal, e.dir) > 0.0f);
        }
        if (e.at_infinity) {
            // Next event estimation's density of the direction is the emission's pos density
            // (a background without a portal, as here: NEE's density does not depend on the point).
            CHECK(lights.nee_density_of_light(e.light, e.point, -e.dir) == Approx(d.pos).epsilon(1e-4));
        }
    }
    for (std::size_t l = 0; l < seen.size(); ++l) {
        INFO("light " << l);
        CHECK(seen[l] > 20);
    }
}

// CameraModel::film_position inverts generate() (pinhole, thin lens, left-handed, near clip), so
// a light vertex splats to the pixel whose camera rays see it.
TEST_CASE("bdpt: the film position of a point seen from the lens is where generate() aimed", "[bdpt][camera]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 0.999f);
    for (int variant = 0; variant < 4; ++variant) {
        Camera c;
        c.position = {0.3f, 1.0f, 5.0f};
        c.look_at = {0.0f, 0.5f, 0.0f};
        c.vfov_degrees = 35.0f;
        if (variant >= 1) c.aperture = 0.2f;
        if (variant >= 2) c.left_handed = true;
        if (variant >= 3) c.near_clip = 1.0f;
        const CameraModel camera(c, 40, 30);
        for (int n = 0; n < 200; ++n) {
            const float fx = 40.0f * unit(rng), fy = 30.0f * unit(rng), u1 = unit(rng), u2 = unit(rng);
            const collision::Ray r = camera.generate(fx, fy, u1, u2);
            const glm::vec3 p = r.origin + 4.0f * r.dir;
            float x = 0.0f, y = 0.0f;
            INFO("variant " << variant);
            REQUIRE(camera.film_position(camera.lens_point(u1, u2), p, 0.0f, x, y));
            CHECK(x == Approx(fx).margin(2e-3));
            CHECK(y == Approx(fy).margin(2e-3));
        }
        // Behind the camera, or before its near clip plane, nothing is seen.
        float x = 0.0f, y = 0.0f;
        const glm::vec3 forward = glm::normalize(c.look_at - c.position);
        CHECK_FALSE(camera.film_position(camera.lens_point(0.5f, 0.5f), c.position - forward, 0.0f, x, y));
        if (c.near_clip > 0.0f)
            CHECK_FALSE(camera.film_position(camera.lens_point(0.5f, 0.5f), c.position + 0.5f * forward, 0.0f, x, y));
    }
}

// vcm's merging radius (issue 39, finding 2): a pbrt scene's `Integrator "sppm"` without a
// `radius` renders with our pixel-footprint radius, not pbrt's default initial radius of 1 scene
// unit (which pbrt shrinks per pixel by photon counts and our (i + 1)^((alpha - 1) / 2) schedule
// barely shrinks: a 1 m blur for the whole render of a room in metres); and the schedule stays
// finite and above 0 for any first radius the loader lets through, however large or small.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"
#include "raytracer/render/integrators/vcm.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// A room 2 m wide and high, open toward the camera, lit by a small ceiling light; pbrt's sppm
// with no radius.
constexpr const char* kSppmRoom = R"(LookAt 0 1 3.5  0 1 0  0 1 0
Camera "perspective" "float fov" [ 45 ]
Film "rgb" "integer xresolution" [ 16 ] "integer yresolution" [ 16 ]
Integrator "sppm" "integer maxdepth" [ 5 ]
WorldBegin
MakeNamedMaterial "white" "string type" "diffuse" "rgb reflectance" [ 0.7 0.7 0.7 ]
MakeNamedMaterial "red" "string type" "diffuse" "rgb reflectance" [ 0.6 0.1 0.1 ]
NamedMaterial "white"
Shape "bilinearmesh" "point3 P" [ -1 0 -1  -1 0 1  1 0 -1  1 0 1 ]
Shape "bilinearmesh" "point3 P" [ -1 2 -1  1 2 -1  -1 2 1  1 2 1 ]
Shape "bilinearmesh" "point3 P" [ -1 0 -1  1 0 -1  -1 2 -1  1 2 -1 ]
Shape "bilinearmesh" "point3 P" [ 1 0 -1  1 0 1  1 2 -1  1 2 1 ]
NamedMaterial "red"
Shape "bilinearmesh" "point3 P" [ -1 0 -1  -1 2 -1  -1 0 1  -1 2 1 ]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 10 10 10 ]
  NamedMaterial "white"
  Shape "bilinearmesh" "point3 P" [ -0.25 1.98 -0.25  0.25 1.98 -0.25  -0.25 1.98 0.25  0.25 1.98 0.25 ]
AttributeEnd
)";

}  // namespace

TEST_CASE("vcm: a pbrt sppm scene without a radius converges to the path tracer's image, not a blur of it",
          "[vcm][pbrt][convergence]") {
    const test::TempDir dir;
    std::vector<std::string> warnings;
    Scene scene = load_pbrt_scene(dir.write("room.pbrt", kSppmRoom), false, warnings);
    REQUIRE(scene.film.integrator == IntegratorKind::Vcm);
    scene.film.clamp_indirect = 0.0f;
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_agrees_with_path(scene, *accel, IntegratorKind::Vcm, 512, 256, 4);
}

// r_i = r_1 (i + 1)^((alpha - 1) / 2) with r_1 anywhere from the smallest denormal to the largest
// float: every iteration's radius and merging density eta = pi r^2 N are finite and above 0, and a
// render at either extreme has finite samples only (before, r_1 = 1e-45 made the grid's cell 0).
TEST_CASE("vcm: the radius schedule stays finite and above 0 for any first radius and iteration", "[vcm]") {
    Scene scene = shipped("cornell-box.json", 8, 8);
    for (const float r1 : {std::numeric_limits<float>::denorm_min(), 1e-45f, 1e-30f, 1.0f, 1e20f, 3e38f,
                           std::numeric_limits<float>::max()}) {
        INFO("vcm_radius " << r1);
        scene.film.vcm_radius = r1;
        const LightSet lights(scene);
        const CameraModel camera(scene.camera, 8, 8);
        const auto accel = make_accel(AccelKind::Bvh, scene);
        BdptIntegrator bdpt(scene, *accel, lights, camera, 5, PlantedDefect::None);
        const VcmIntegrator vcm(scene, *accel, camera, bdpt, 5);
        for (const int i : {0, 1, 1000, 1 << 20, std::numeric_limits<int>::max() - 1}) {
            INFO("iteration " << i);
            const float r = vcm.radius(i);
            CHECK(std::isfinite(r));
            CHECK(r > 0.0f);
            const float eta = vcm.merge_density(i);
            CHECK(std::isfinite(eta));
            CHECK(eta > 0.0f);
        }
    }
    const auto accel = make_accel(AccelKind::Bvh, scene);
    for (const float r1 : {std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max()}) {
        INFO("vcm_radius " << r1);
        scene.film.vcm_radius = r1;
        CHECK(render_as(scene, *accel, IntegratorKind::Vcm, 2, 1).stats.nonfinite_samples == 0);
    }
}

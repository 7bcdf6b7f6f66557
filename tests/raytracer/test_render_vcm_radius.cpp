// vcm's merging radius (issue 39, finding 2): a pbrt scene's `Integrator "sppm"` without a
// `radius` renders with our pixel-footprint radius, not pbrt's default initial radius of 1 scene
// unit (which pbrt shrinks per pixel by photon counts and our (i + 1)^((alpha - 1) / 2) schedule
// barely shrinks: a 1 m blur for the whole render of a room in metres); and the schedule stays
// finite and above 0 for any first radius the loader lets through, however large or small.
#include <catch2/catch.hpp>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"
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
    Scene scene = load_scene(dir.write("room.pbrt", kSppmRoom));
    REQUIRE(scene.film.integrator == IntegratorKind::Vcm);
    scene.film.clamp_indirect = 0.0f;
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_agrees_with_path(scene, *accel, IntegratorKind::Vcm, 512, 256, 4);
}

// vcm's merging takes a photon only from a surface facing the camera vertex's way (issue 39,
// finding 3): a photon is light arriving at its own surface, and counting it at a vertex on a
// surface turned another way (a wall next to a lit floor) leaks light around corners, blurred over
// the merging radius.
#include <catch2/catch.hpp>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// A white wall (x = 0, facing +x) standing on a dim floor (y = 0) under a sun at 45 degrees from +x
// (1 degree wide: bdpt and vcm disagree with the path tracer under a sun of diameter 0 on
// today's main whatever the merging, a separate matter).
// A plate at y = 1 over the wall's foot casts a shadow that ends exactly at the corner: the floor is
// in full sun up to the wall, the wall in shadow, lit only by the floor's faint bounce. Photons on
// the floor next to the corner arrive from the wall's side (from the sun), so the BSDF at a wall
// vertex alone does not refuse them.
constexpr const char* kShadowedCorner = R"({
  "camera": {"position": [2.5, 0.5, 0], "look_at": [0, 0.4, 0], "fov": 50},
  "film": {"width": 24, "height": 16, "max_depth": 5, "vcm_radius": 0.2},
  "materials": {"white": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]},
                "dim": {"type": "diffuse", "albedo": [0.1, 0.1, 0.1]}},
  "objects": [
    {"type": "quad", "corner": [0, 0, -2], "edge_u": [0, 0, 4], "edge_v": [4, 0, 0], "material": "dim"},
    {"type": "quad", "corner": [0, 0, -2], "edge_u": [0, 1, 0], "edge_v": [0, 0, 4], "material": "white"},
    {"type": "quad", "corner": [0, 1, -2], "edge_u": [1, 0, 0], "edge_v": [0, 0, 4], "material": "dim"}
  ],
  "lights": [{"type": "directional", "direction": [-1, -1, 0], "irradiance": [1, 1, 1], "angular_diameter": 1}]
})";

}  // namespace

TEST_CASE("vcm: no light leaks around a corner: a photon on the lit floor is not merged at the shadowed wall",
          "[vcm][convergence]") {
    const test::TempDir dir;
    const Scene scene = load_scene(dir.write("corner.json", kShadowedCorner));
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_agrees_with_path(scene, *accel, IntegratorKind::Vcm, 512, 256, 4);
}

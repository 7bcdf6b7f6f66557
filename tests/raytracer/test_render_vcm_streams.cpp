// vcm's light subpaths and camera subpaths draw distinct random numbers (issue 39, finding 1). vcm
// traces a pixel's light subpath in the light pass and its camera subpath in the camera pass, and
// joins the two; with `--sampler independent` (the sampler reference-check forces), whose stream
// ignores dimensions, both passes once built the same stream for (seed, pixel, sample), so the
// camera subpath replayed the numbers of the light subpath it is joined to (its film offset was the
// light choice, its first bounce's direction shared a number with the emission's). The Sobol
// sampler separates them by dimension (bdpt.cpp's interleaved slots); the independent one now by a
// stream of its own (sampler.hpp). The first z-test guards the change on a scene where connections
// carry the light; on the code before it, it passed too (max z 1.4 of 3.3 in 4 blocks at these
// sizes): there the correlation's bias is below what the test resolves. The second scene is built
// so that the replay shows: every pixel is half a white stripe, half a black one, so a camera
// sample's film offset decides what it sees; the same number, replayed as the light subpath's
// light choice, decided which of two equal lamps it was joined to; one lamp lights the stripes
// only through a reflector (connections carry nearly all of it: the lamp is beside the reflector,
// far from the stripes, and a merging radius of 1e-4 leaves merges no weight), the other shines
// into the void. With one stream, the white halves were joined only to one lamp's subpaths: at
// 4d5f2e1, `render --integrator vcm --sampler independent --spp 256` of it averaged 0.0026 where
// the path tracer gives 0.0186 at 16384 spp (and vcm now 0.0185 at 2048), every 4 x 4 block 2.5
// to 20 times too dark.
#include <catch2/catch.hpp>

#include <variant>

#include <nlohmann/json.hpp>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"
#include "raytracer/scene/load_scene_document.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// cornell-box with its light lowered and turned to face the ceiling: no camera vertex below it
// sees its emitting side and no camera path finds it, so next event estimation and emitter hits
// bring nothing: the room is lit by the ceiling's bounce, which connections (light vertex on the
// ceiling joined to camera vertices), light tracing and merging carry.
Scene ceiling_lit_box(int width, int height) {
    Scene scene = shipped("cornell-box.json", width, height);
    for (Object& o : scene.objects) {
        if (o.name != "light") continue;
        auto& q = std::get<collision::Quad>(o.shape);
        std::swap(q.edge_u, q.edge_v);  // the front face, edge_u x edge_v, now points up
        q.corner.y = 450.0f;
    }
    return scene;
}

// The stripes: a 2 x 2 quad filling a 16 x 16 view, 32 stripes across (two per pixel column), lit
// by a lamp behind the camera facing up at a reflector above the view; a second lamp, the same,
// faces down into the black void.
Scene stripes_scene() {
    const char* text = R"({
      "camera": { "position": [0, 0, -1], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 90 },
      "film": { "width": 16, "height": 16, "spp": 64, "max_depth": 4, "vcm_radius": 0.0001, "filter": { "type": "box" } },
      "background": { "color": [0, 0, 0] },
      "materials": {
        "stripes": { "type": "diffuse",
                     "albedo": { "checker": { "a": [0.9, 0.9, 0.9], "b": [0, 0, 0], "scale": 32, "uv_scale": [1, 0.015625] } } },
        "white": { "type": "diffuse", "albedo": [0.9, 0.9, 0.9] },
        "light": { "type": "emissive", "emission": [12.5, 12.5, 12.5] }
      },
      "objects": [
        { "name": "stripes", "type": "quad", "corner": [-1, -1, 0], "edge_u": [2, 0, 0], "edge_v": [0, 2, 0], "material": "stripes" },
        { "name": "reflector", "type": "quad", "corner": [-3, 1.5, -3], "edge_u": [6, 0, 0], "edge_v": [0, 0, 3], "material": "white" },
        { "name": "lamp", "type": "quad", "corner": [-0.2, 0.9, -1.8], "edge_u": [0, 0, 0.4], "edge_v": [0.4, 0, 0], "material": "light" },
        { "name": "lost lamp", "type": "quad", "corner": [-0.2, -5, -0.85], "edge_u": [0.4, 0, 0], "edge_v": [0, 0, 0.4], "material": "light" }
      ]
    })";
    return load_scene_document(nlohmann::json::parse(text), "stripes.json");
}

}  // namespace

TEST_CASE("vcm with the independent sampler: pixels half white, half black, lit through connections, converge to the path tracer",
          "[vcm][convergence][sampler]") {
    const Scene scene = stripes_scene();
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_agrees_with_path(scene, *accel, IntegratorKind::Vcm, 1024, 256, 4, SamplerKind::Independent);
}

TEST_CASE("vcm with the independent sampler: converges to the path tracer where connections carry the light",
          "[vcm][convergence][sampler]") {
    const Scene scene = ceiling_lit_box(16, 16);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_agrees_with_path(scene, *accel, IntegratorKind::Vcm, 512, 256, 4, SamplerKind::Independent);
}

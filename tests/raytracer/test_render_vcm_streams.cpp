// vcm's light subpaths and camera subpaths draw distinct random numbers (issue 39, finding 1). vcm
// traces a pixel's light subpath in the light pass and its camera subpath in the camera pass, and
// joins the two; with `--sampler independent` (the sampler reference-check forces), whose stream
// ignores dimensions, both passes once built the same stream for (seed, pixel, sample), so the
// camera subpath replayed the numbers of the light subpath it is joined to (its film offset was the
// light choice, its first bounce's direction shared a number with the emission's). The Sobol
// sampler separates them by dimension (bdpt.cpp's interleaved slots); the independent one now by a
// stream of its own (sampler.hpp). This z-test guards the change on a scene where connections carry
// the light; on the code before it, it passed too (max z 1.4 of 3.3 in 4 blocks at these sizes):
// the correlation's bias is below what the test resolves at this cost, so it shows the fix keeps
// vcm converged, not that the old streams were wrong.
#include <catch2/catch.hpp>

#include <variant>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"

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

}  // namespace

TEST_CASE("vcm with the independent sampler: converges to the path tracer where connections carry the light",
          "[vcm][convergence][sampler]") {
    const Scene scene = ceiling_lit_box(16, 16);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_agrees_with_path(scene, *accel, IntegratorKind::Vcm, 512, 256, 4, SamplerKind::Independent);
}

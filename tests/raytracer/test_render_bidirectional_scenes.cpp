// bdpt and vcm converge to the path tracer's image on every other shipped scene where the path
// tracer converges (cornell-box, default and caustic have their own tests): spheres-field's many
// small lights, smallpt's glass and mirror under a large light, the primitives' analytic shapes,
// a mesh, the showcase's materials and the motion blur scene. Tiny images, the block z-test
// (convergence_harness.hpp) on the path tracer's longer render.
#include <catch2/catch.hpp>

#include <tuple>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

TEST_CASE("bdpt and vcm: converge to the path tracer's image on the other shipped scenes", "[bdpt][vcm][convergence]") {
    for (const auto& [name, w, h] : {std::tuple{"spheres-field.json", 24, 16}, std::tuple{"smallpt.json", 24, 18},
                                     std::tuple{"primitives.json", 24, 16}, std::tuple{"mesh.json", 24, 16},
                                     std::tuple{"showcase.json", 24, 16}, std::tuple{"motion.json", 24, 16}}) {
        INFO(name);
        const Scene scene = shipped(name, w, h);
        const auto accel = make_accel(AccelKind::Bvh, scene);
        check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
    }
}

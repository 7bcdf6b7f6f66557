// A room lit only by a uniform sky through a window (scenes/sky-window.json, issue 39 finding 6):
// the sky sampled by next event estimation through the window as its portal converges to the image
// of the estimator that does not sample it (BSDF sampling alone, what the path tracer did before,
// and still does for a uniform sky without a portal) with far less noise; a portal that covers
// only part of the opening stays unbiased; bdpt and vcm converge to the path tracer under the
// portalled sky; the pbrt form's portal is imported onto the same window; the key's messages.
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"
#include "pbrt_test_support.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// Tiny and depth 5: the floor and the walls lit directly and by a few bounces.
Scene sky_window_room(bool portal) {
    Scene s = shipped("sky-window.json", 32, 24);
    REQUIRE(s.background.has_portal);
    s.background.has_portal = portal;
    s.film.max_depth = 5;
    return s;
}

struct PortalCheck {
    RenderResult reference, portal;
};

// The room with its portal (`portalled`, `spp` at seed `seed`) against the same room without it
// by BSDF sampling alone (1024 spp, seed 1): the block z-test must pass.
PortalCheck check_portal_against_bsdf_only(const Scene& portalled, int spp, std::uint64_t seed) {
    Scene plain = portalled;
    plain.background.has_portal = false;
    const auto accel = make_accel(AccelKind::Bvh, portalled);
    PortalCheck c{render_as(plain, *accel, IntegratorKind::Path, 1024, 1, PlantedDefect::None, 0, 0, Sampling::BsdfOnly),
                  render_as(portalled, *accel, IntegratorKind::Path, spp, seed)};
    const BlockTestResult t = against_path(c.reference, c.portal, 4);
    INFO(t.summary());
    CHECK(t.pass());
    CHECK(c.portal.stats.nonfinite_samples == 0);
    return c;
}

}  // namespace

TEST_CASE("sky through a window: sampled through its portal, the same image as BSDF sampling alone, far less noisy",
          "[render][portal][convergence]") {
    const Scene plain = sky_window_room(false), portalled = sky_window_room(true);
    // Without the portal the uniform sky is no light (scene_lights.cpp): BSDF sampling alone finds it.
    CHECK_FALSE(LightSet(plain).background_is_light());
    CHECK(LightSet(portalled).background_is_light());
    const auto [reference, portal] = check_portal_against_bsdf_only(portalled, 64, 3);
    // Noise at equal samples per pixel: the portal's directions all reach the sky (but for the
    // room's own occluders), BSDF directions seldom do.
    const double bsdf_variance_64 = mean_pixel_variance(reference.variance) * (1024.0 / 64.0);
    const double v_portal = mean_pixel_variance(portal.variance);
    INFO("mean pixel variance at 64 spp: BSDF only " << bsdf_variance_64 << ", through the portal " << v_portal);
    CHECK(v_portal < 0.25 * bsdf_variance_64);
}

TEST_CASE("sky through a window: a portal covering only part of the opening stays unbiased", "[render][portal][convergence]") {
    // Without the wall right of the window the opening runs on to the room's corner (z from 2 to
    // 5); the portal still covers only z from 2 to 3.5. The rest is found by BSDF sampling alone.
    Scene wide = sky_window_room(true);
    std::erase_if(wide.objects, [](const Object& o) { return o.name == "window right"; });
    REQUIRE(wide.objects.size() == sky_window_room(true).objects.size() - 1);
    check_portal_against_bsdf_only(wide, 128, 4);
}

TEST_CASE("sky through a window: bdpt and vcm converge to the path tracer under the portalled sky", "[render][portal][bdpt][vcm][convergence]") {
    const Scene scene = sky_window_room(true);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_bidirectional_agree_with_path(scene, *accel, 512, 128, 4);
}

TEST_CASE("sky through a window: the pbrt scene's constant infinite light keeps its portal", "[pbrt][portal]") {
    std::vector<std::string> warnings;
    const Scene pbrt = load_pbrt_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / "pbrt" / "sky-window.pbrt",
                                       true, warnings);
    CHECK(warnings.empty());
    const Scene json = load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / "sky-window.json");
    CHECK(pbrt.background.kind == Background::Kind::Constant);
    CHECK(pbrt.background.color == json.background.color);
    REQUIRE(pbrt.background.has_portal);
    for (std::size_t i = 0; i < 4; ++i) CHECK(pbrt.background.portal[i] == json.background.portal[i]);
}

TEST_CASE("portal key: four corners of a rectangle, else a message naming the key", "[scene][portal]") {
    const sweeptrace::test::TempDir dir;
    const auto load_with = [&](const std::string& portal) {
        const auto file = dir.write("s.json", R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
            "film": {"width": 4, "height": 4}, "materials": {"m": {"type": "diffuse"}},
            "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
            "background": {"color": [1, 1, 1], "portal": )" + portal + "}}");
        return load_scene(file);
    };
    CHECK(load_with("[[0, 0, 0], [1, 0, 0], [1, 2, 0], [0, 2, 0]]").background.has_portal);
    CHECK_THROWS_WITH(load_with("[[0, 0, 0], [1, 0, 0], [1, 2, 0]]"), Catch::Contains("background.portal") && Catch::Contains("4 corners"));
    CHECK_THROWS_WITH(load_with("[[0, 0, 0], [1, 0, 0], [1.5, 2, 0], [0, 2, 0]]"),
                      Catch::Contains("background.portal") && Catch::Contains("not perpendicular"));
    CHECK_THROWS_WITH(load_with("[[0, 0, 0], [1, 0, 0], [1, 0, 0], [0, 2, 0]]"), Catch::Contains("must differ"));
}

// film.clamp_indirect (render/film/radiance_clamp.hpp): which contributions it limits, how far, and
// that on a real scene it only ever removes light, leaves direct views of emitters exact and is
// off by default.
#include <catch2/catch.hpp>

#include <filesystem>

#include "raytracer/accel/accel.hpp"
#include "raytracer/render/film/radiance_clamp.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"

using namespace sweeptrace;

namespace {

const glm::vec3 bright{30.0f, 12.0f, 6.0f};  // largest component 30: well over the limit below

}  // namespace

TEST_CASE("indirect clamp: direct light, seen through glass or not, keeps its value", "[render][clamp]") {
    IndirectClamp c(4.0f);
    CHECK(c.found(bright, 1) == bright);  // an emitter the camera sees
    c.scatter_at(1, true);                // through a glass surface
    c.scatter_at(2, true);
    CHECK(c.found(bright, 3) == bright);  // an emitter seen through the glass
    c.scatter_at(3, false);               // the first rough surface, seen through the glass
    CHECK(c.light_sample(bright, 3) == bright);  // its direct lighting, by a light sample
    CHECK(c.found(bright, 4) == bright);         // and by BSDF sampling hitting the emitter
}

TEST_CASE("indirect clamp: caustics and multiple scattering are limited to the largest component", "[render][clamp]") {
    IndirectClamp caustic(4.0f);  // diffuse ground -> glass -> glass -> a bulb
    caustic.scatter_at(1, false);
    caustic.scatter_at(2, true);
    caustic.scatter_at(3, true);
    const glm::vec3 got = caustic.found(bright, 4);
    CHECK(got.x == Approx(4.0f));
    CHECK(got.y == Approx(4.0f * 12.0f / 30.0f));  // the colour is kept: one scale for all channels
    CHECK(got.z == Approx(4.0f * 6.0f / 30.0f));

    IndirectClamp bounce(4.0f);  // diffuse -> diffuse, then a light sample
    bounce.scatter_at(1, false);
    bounce.scatter_at(2, false);
    CHECK(bounce.light_sample(bright, 2).x == Approx(4.0f));
    CHECK(bounce.light_sample(glm::vec3(3.0f, 1.0f, 0.5f), 2) == glm::vec3(3.0f, 1.0f, 0.5f));  // under the limit

    IndirectClamp off(0.0f);  // the default: nothing limited
    off.scatter_at(1, false);
    off.scatter_at(2, false);
    CHECK(off.found(bright, 3) == bright);
    CHECK(off.light_sample(bright, 2) == bright);
}

TEST_CASE("indirect clamp on the default scene: only removes light, never from what is directly lit", "[render][clamp]") {
    Scene scene = load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / "default.json");
    REQUIRE(scene.film.clamp_indirect > 0.0f);  // the scene the README's first command renders
    scene.film.width = 64;
    scene.film.height = 36;
    const auto accel = make_accel(AccelKind::Bvh, scene);
    RenderOptions o;
    o.spp = 8;
    o.seed = 3;
    o.threads = 2;
    const Image on = render(scene, *accel, o).image;
    Scene unclamped = scene;
    unclamped.film.clamp_indirect = 0.0f;
    const Image off = render(unclamped, *accel, o).image;
    REQUIRE(on.pixels.size() == off.pixels.size());
    // The same seed draws the same numbers for every path, and the clamp only scales
    // contributions down, so no channel of any pixel can gain.
    int lower = 0;
    for (std::size_t i = 0; i < on.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) REQUIRE(on.pixels[i][c] <= off.pixels[i][c]);
        if (on.pixels[i] != off.pixels[i]) ++lower;
    }
    CHECK(lower > 0);                                    // the caustics were limited somewhere
    CHECK(lower < static_cast<int>(on.pixels.size()) / 4);  // and most pixels kept every sample
    // With one vertex, every contribution is direct: the clamp must change nothing.
    o.max_depth = 1;
    const Image on1 = render(scene, *accel, o).image;
    const Image off1 = render(unclamped, *accel, o).image;
    CHECK(on1.pixels == off1.pixels);
}

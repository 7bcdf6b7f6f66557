// The 8-bit display transform (exposure in stops, clamp and ACES curves; linear outputs are
// covered by the CLI test) and the warning about one-sided emitters that face nothing.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "convergence_harness.hpp"
#include "raytracer/render/film/tone_map.hpp"
#include "raytracer/scene/emitter_check.hpp"
#include "raytracer/scene/load_scene.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

TEST_CASE("display: exposure is in stops and the clamp curve is the identity on [0, 1]", "[render][display]") {
    Image img(3, 1);
    img.pixels = {glm::vec3(0.1f, 0.25f, 0.4f), glm::vec3(-1.0f, 2.0f, std::nanf("")),
                  glm::vec3(std::numeric_limits<float>::infinity())};
    const Image d0 = to_display(img);
    CHECK(d0.pixels[0] == img.pixels[0]);
    CHECK(d0.pixels[1] == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(d0.pixels[2] == glm::vec3(1.0f));
    const Image up = to_display(img, 1.0f);  // one stop: twice the radiance, exactly
    CHECK(up.pixels[0] == 2.0f * img.pixels[0]);
    const Image down = to_display(img, -2.0f);
    CHECK(down.pixels[0] == 0.25f * img.pixels[0]);
}

TEST_CASE("display: the ACES curve is Narkowicz's fit, monotone, 0 at 0 and 1 from 7.24 on", "[render][display]") {
    auto fit = [](double v) { return v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14); };
    for (double v : {0.01, 0.18, 0.5, 1.0, 3.0, 7.0})
        CHECK(tone_curve(ToneCurve::Aces, static_cast<float>(v)) == Approx(fit(v)).epsilon(1e-6));
    CHECK(tone_curve(ToneCurve::Aces, 0.18f) == Approx(0.2669).epsilon(1e-3));
    CHECK(tone_curve(ToneCurve::Aces, 0.0f) == 0.0f);
    CHECK(tone_curve(ToneCurve::Aces, -3.0f) == 0.0f);
    CHECK(tone_curve(ToneCurve::Aces, std::nanf("")) == 0.0f);
    CHECK(tone_curve(ToneCurve::Aces, 7.3f) == 1.0f);
    CHECK(tone_curve(ToneCurve::Aces, std::numeric_limits<float>::infinity()) == 1.0f);
    float last = 0.0f;
    for (int i = 1; i <= 2000; ++i) {
        const float f = tone_curve(ToneCurve::Aces, 0.005f * static_cast<float>(i));
        REQUIRE(f >= last);
        last = f;
    }
    CHECK(to_display(Image(1, 1), 0.0f, ToneCurve::Aces).pixels[0] == glm::vec3(0.0f));
}

namespace {

// A floor quad (front up) and a quad light 2 above it, front down unless `flipped`.
Scene floor_and_light(bool flipped, bool two_sided) {
    Scene scene = empty_scene(4, 4);
    scene.source = "room.json";
    add_object(scene, collision::Quad{{-1.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 2.0f}, {2.0f, 0.0f, 0.0f}},
               add_material(scene, diffuse(0.5f)), glm::mat4(1.0f), "objects[0] (quad)");
    Material lamp;
    lamp.type = Material::Type::Emissive;
    lamp.emission = glm::vec3(4.0f);
    lamp.two_sided_emission = two_sided;
    lamp.name = "lamp";
    const glm::vec3 u(0.5f, 0.0f, 0.0f), v(0.0f, 0.0f, 0.5f);  // u x v points down
    add_object(scene, flipped ? collision::Quad{{0.0f, 2.0f, 0.0f}, v, u} : collision::Quad{{0.0f, 2.0f, 0.0f}, u, v},
               add_material(scene, lamp), glm::mat4(1.0f), "objects[1] (quad)");
    return scene;
}

}  // namespace

TEST_CASE("emitter check: a one-sided light turned away from every other object is reported", "[scene][display]") {
    CHECK(emitters_facing_nothing(floor_and_light(false, false)).empty());
    const auto w = emitters_facing_nothing(floor_and_light(true, false));
    REQUIRE(w.size() == 1);
    CHECK_THAT(w[0], Catch::StartsWith("room.json: objects[1] (quad): one-sided emitter (material \"lamp\")"));
    CHECK(emitters_facing_nothing(floor_and_light(true, true)).empty());  // two-sided lights both ways
    // Turned about x by 180 degrees by its transform, the flipped light faces the floor again.
    Scene turned = floor_and_light(true, false);
    turned.objects[1].transform = Transform::from_matrix(
        glm::translate(glm::mat4(1.0f), {0.0f, 4.0f, 0.0f}) * glm::rotate(glm::mat4(1.0f), glm::radians(180.0f), {1.0f, 0.0f, 0.0f}));
    CHECK(emitters_facing_nothing(turned).empty());
    // A disk and a triangle go through their homes' front() the same way.
    Scene disk = floor_and_light(false, false);
    disk.objects[1].shape = collision::Disk{{0.0f, 2.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.3f};
    CHECK(emitters_facing_nothing(disk).size() == 1);
    disk.objects[1].shape = collision::Triangle{{0.0f, 2.0f, 0.0f}, {1.0f, 2.0f, 0.0f}, {0.0f, 2.0f, 1.0f}};
    CHECK(emitters_facing_nothing(disk).empty());  // (b - a) x (c - a) = -y: faces the floor
}

TEST_CASE("emitter check: the Cornell box with its light's edges swapped is reported, as it is not", "[scene][display]") {
    Scene scene = load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / "cornell-box.json");
    CHECK(emitters_facing_nothing(scene).empty());
    for (Object& o : scene.objects)
        if (o.name == "light") {
            collision::Quad& q = std::get<collision::Quad>(o.shape);
            std::swap(q.edge_u, q.edge_v);
        }
    // The ceiling 1 unit above faces it, so only the second rule (the scene's centre) fires.
    const auto w = emitters_facing_nothing(scene);
    REQUIRE(w.size() == 1);
    CHECK_THAT(w[0], Catch::Contains("light: one-sided emitter (material \"light\") faces away from the camera and from the centre"));
}

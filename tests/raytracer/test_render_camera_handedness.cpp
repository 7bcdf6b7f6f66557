// camera.handedness (render/camera.hpp): a left-handed camera draws the mirror image of the
// right-handed one. Its ray through film point (x, y) with lens sample (u1, u2) is the
// right-handed camera's ray through (W - x, y) with the lens point mirrored too (u1 -> 1 - u1,
// which negates the concentric disk's x): the same ray, drawn in the mirrored pixel.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "raytracer/render/camera.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_load_error.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using sweeptrace::test::TempDir;

namespace {

Camera oblique_camera(bool left, float aperture) {
    Camera c;
    c.position = {1.0f, 2.0f, 3.0f};
    c.look_at = {-0.5f, 0.2f, -1.0f};
    c.up = {0.1f, 1.0f, 0.2f};
    c.vfov_degrees = 35.0f;
    c.aperture = aperture;
    c.focus_distance = 4.0f;
    c.left_handed = left;
    return c;
}

}  // namespace

TEST_CASE("camera: a left-handed camera's rays are the right-handed camera's, mirrored left to right", "[render][camera]") {
    const int w = 40, h = 24;
    for (const float aperture : {0.0f, 0.3f}) {
        const Camera lc = oblique_camera(true, aperture), rc = oblique_camera(false, aperture);
        const CameraModel left(lc, w, h), right(rc, w, h);
        const glm::vec3 forward = glm::normalize(rc.look_at - rc.position);
        const glm::vec3 r = glm::normalize(glm::cross(forward, rc.up));  // the right-handed image's right
        Rng rng(11, 0, 0);
        for (int i = 0; i < 2000; ++i) {
            const float x = rng.uniform() * w, y = rng.uniform() * h, u1 = rng.uniform(), u2 = rng.uniform();
            const collision::Ray a = left.generate(x, y, u1, u2);
            const collision::Ray b = right.generate(static_cast<float>(w) - x, y, 1.0f - u1, u2);
            INFO("aperture " << aperture << ", film (" << x << ", " << y << "), lens (" << u1 << ", " << u2 << ")");
            CHECK(glm::length(a.origin - b.origin) < 2e-6f * (1.0f + glm::length(rc.position)));
            CHECK(glm::length(a.dir - b.dir) < 2e-6f);
        }
        // The centre of the image looks where the right-handed camera does, and up stays up.
        CHECK(glm::length(left.generate(0.5f * w, 0.5f * h, 0.5f, 0.5f).dir - forward) < 1e-6f);
        const glm::vec3 top = left.generate(0.5f * w, 0.0f, 0.5f, 0.5f).dir;
        CHECK(glm::dot(top, rc.up) > glm::dot(forward, rc.up));
        // Its image's right is up x forward, the other side of the right-handed camera's.
        const glm::vec3 edge = left.generate(static_cast<float>(w), 0.5f * h, 0.5f, 0.5f).dir;
        CHECK(glm::dot(edge, r) < -0.1f);
    }
}

TEST_CASE("camera: handedness is read from the scene, \"right\" by default, anything else refused", "[render][camera][scene]") {
    const TempDir dir;
    auto scene_with = [](const std::string& camera_extra) {
        return std::string(R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0])") + camera_extra +
               R"(}, "film": {"width": 8, "height": 8, "spp": 1}, "materials": {"m": {"type": "diffuse"}},
                  "objects": [{"type": "sphere", "radius": 1, "material": "m"}]})";
    };
    CHECK_FALSE(load_scene(dir.write("a.json", scene_with(""))).camera.left_handed);
    CHECK_FALSE(load_scene(dir.write("b.json", scene_with(R"(, "handedness": "right")"))).camera.left_handed);
    CHECK(load_scene(dir.write("c.json", scene_with(R"(, "handedness": "left")"))).camera.left_handed);
    CHECK_THAT(sweeptrace::test::load_error(dir, scene_with(R"(, "handedness": "Left")")),
               Catch::Contains("camera.handedness: must be \"right\" (ours, the default) or \"left\""));
    CHECK_THAT(sweeptrace::test::load_error(dir, scene_with(R"(, "handedness": 1)")), Catch::Contains("camera.handedness"));
}

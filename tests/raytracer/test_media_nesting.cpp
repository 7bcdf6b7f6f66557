// The nesting check (render/media/media_nesting.hpp): the shipped scenes whose media nest pass;
// an open boundary (an interface quad) is judged by the side the camera is on. The contradicting
// scenes as the user meets them (JSON and pbrt, exit 2, nothing written) are the bad-input
// corpus's media-nesting-* and pbrt-medium-nesting.
#include <catch2/catch.hpp>

#include <filesystem>

#include "convergence_harness.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/media/media_nesting.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "render_test_scenes.hpp"

using namespace sweeptrace;

namespace {

void check_nesting(const Scene& scene) {
    const auto accel = make_accel(AccelKind::Bvh, scene);
    check_media_nesting(scene, *accel);
}

// An interface quad in the plane z = 0 facing +z, fog behind it (its inside), vacuum in front.
Scene fog_behind_quad(const glm::vec3& camera, std::int32_t camera_medium) {
    Scene scene = sweeptrace::testing::empty_scene(8, 8);
    Medium fog;
    fog.name = "fog";
    fog.sigma_s = glm::vec3(1.0f);
    scene.media.push_back(fog);
    Material boundary;
    boundary.type = Material::Type::Interface;
    sweeptrace::testing::add_object(scene, collision::Quad{glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f)},
                                    sweeptrace::test::add_material(scene, boundary), glm::mat4(1.0f), "fog curtain");
    scene.objects.back().media.inside = 0;
    scene.camera.position = camera;
    scene.camera.look_at = glm::vec3(0.0f);
    scene.camera.medium = camera_medium;
    return scene;
}

}  // namespace

TEST_CASE("media nesting: the shipped scenes with media nest consistently", "[media][nesting]") {
    // (The shared volumetric-caustic and staircase2: test_pbrt_media.cpp.)
    for (const char* name : {"fog.json", "media/smoke.json"}) {
        INFO(name);
        CHECK_NOTHROW(check_nesting(load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / name)));
    }
}

TEST_CASE("media nesting: an open interface quad bounds its media on the side each probe leaves from", "[media][nesting]") {
    // Its outward probe leaves toward the camera and meets nothing; the camera's probe toward it
    // arrives at its front, where vacuum is.
    CHECK_NOTHROW(check_nesting(fog_behind_quad(glm::vec3(0.0f, 0.0f, 3.0f), -1)));
    CHECK_NOTHROW(check_nesting(fog_behind_quad(glm::vec3(0.0f, 0.0f, -3.0f), 0)));
    // Behind it, in what it says is fog, a camera that says vacuum is refused, naming the quad.
    CHECK_THROWS_WITH(check_nesting(fog_behind_quad(glm::vec3(0.0f, 0.0f, -3.0f), -1)),
                      Catch::Contains("the camera's \"medium\" is vacuum") && Catch::Contains("fog curtain, has \"fog\""));
    // In front of it a camera that says fog is refused too.
    CHECK_THROWS_WITH(check_nesting(fog_behind_quad(glm::vec3(0.0f, 0.0f, 3.0f), 0)),
                      Catch::Contains("the camera's \"medium\" is \"fog\"") && Catch::Contains("fog curtain, has vacuum"));
}

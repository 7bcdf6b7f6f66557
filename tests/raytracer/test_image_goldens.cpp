// Every scene with both accelerators against its golden, and the mutation checks: the same
// comparison must reject renders with a planted defect and accept a render with another seed.
// Criterion and thresholds: reference_images/README.md.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "golden_harness.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

constexpr std::uint64_t test_seed = 1;  // the goldens use another seed (goldens.txt)

void check_scene(const std::string& scene_name, AccelKind accel, const char* accel_name) {
    const GoldenSpec& spec = golden_spec(scene_name);
    const Scene scene = load_golden_scene(spec);
    const RenderResult result = render_for_test(scene, accel, spec, test_seed);
    REQUIRE(result.stats.nonfinite_samples == 0);
    const GoldenVerdict v = compare_to_golden(spec, result, scene_name + "-" + accel_name, true);
    INFO(v.block.summary());
    CHECK(v.accepted());
    WARN(scene_name << " " << accel_name << ": " << v.block.summary());  // the margin, on record
}

std::size_t object_named(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].name == name) return i;
    FAIL("scene has no object named " << name);
    return 0;
}

void expect_rejected(const GoldenSpec& spec, const Scene& scene, const std::string& label,
                     PlantedDefect defect = PlantedDefect::None) {
    const RenderResult result = render_for_test(scene, AccelKind::Bvh, spec, test_seed, defect);
    const GoldenVerdict v = compare_to_golden(spec, result, label, false);
    INFO(v.block.summary());
    CHECK_FALSE(v.accepted());
    // Printed so the margin (max z over the limit) is on record in the test log.
    WARN(label << ": " << v.block.summary());
}

}  // namespace

// Hidden (never run by ctest): tools/make-goldens.sh runs it to regenerate reference_images/,
// for the scenes named in SWEEPTRACE_GOLDEN_SCENES (space-separated; all when unset).
TEST_CASE("make goldens", "[.make-goldens]") {
    const char* only = std::getenv("SWEEPTRACE_GOLDEN_SCENES");
    std::string wanted;
    if (only && *only) (wanted = " ").append(only).append(" ");
    for (const GoldenSpec& spec : read_golden_specs()) {
        if (!wanted.empty() && wanted.find(" " + spec.scene + " ") == std::string::npos) continue;
        std::printf("make-goldens: %s %dx%d, %d spp, max depth %d, seed %llu\n", spec.scene.c_str(), spec.width,
                    spec.height, spec.golden_spp, spec.max_depth, static_cast<unsigned long long>(spec.golden_seed));
        std::fflush(stdout);
        make_golden(spec);
    }
}

#define GOLDEN_TEST(scene, tag)                                                                               \
    TEST_CASE("golden " scene " bvh", "[image][golden]") { check_scene(scene, AccelKind::Bvh, "bvh"); }      \
    TEST_CASE("golden " scene " embree", "[image][golden]") { check_scene(scene, AccelKind::Embree, "embree"); }

GOLDEN_TEST("cornell-box", cornell)
GOLDEN_TEST("smallpt", smallpt)
GOLDEN_TEST("primitives", primitives)
GOLDEN_TEST("mesh", mesh)
GOLDEN_TEST("default", default)
GOLDEN_TEST("showcase", showcase)
GOLDEN_TEST("spheres-field", spheres_field)
GOLDEN_TEST("motion", motion)
GOLDEN_TEST("caustic", caustic)  // rendered by bdpt, its film.integrator
GOLDEN_TEST("sky-window", sky_window)
GOLDEN_TEST("fog", fog)  // a homogeneous medium and an absorbing glass interior

// A scene added to scenes/ without a golden would go untested: every top-level scenes/*.json
// needs its goldens.txt line, its golden and variance files, and both image tests registered.
TEST_CASE("every scene in scenes/ has a golden and its image tests", "[image][golden]") {
    std::vector<std::string> registered;
    for (const Catch::TestCase& t : Catch::getRegistryHub().getTestCaseRegistry().getAllTests())
        registered.push_back(t.name);
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        ++scenes;
        const std::string name = entry.path().stem().string();
        INFO("scenes/" << name << ".json");
        const auto& specs = read_golden_specs();
        const auto spec = std::find_if(specs.begin(), specs.end(), [&](const GoldenSpec& g) { return g.scene == name; });
        REQUIRE(spec != specs.end());  // add its line to reference_images/goldens.txt
        CHECK(std::filesystem::is_regular_file(golden_image_path(*spec)));     // bash tools/make-goldens.sh build NAME
        CHECK(std::filesystem::is_regular_file(golden_variance_path(*spec)));
        for (const char* accel : {" bvh", " embree"})  // GOLDEN_TEST(NAME) above
            CHECK(std::find(registered.begin(), registered.end(), "golden " + name + accel) != registered.end());
    }
    CHECK(scenes >= 7);  // the directory was read: the seven scenes of today at least
}

TEST_CASE("golden mutation: another seed is accepted", "[image][golden][mutation]") {
    const GoldenSpec& spec = golden_spec("cornell-box");
    const Scene scene = load_golden_scene(spec);
    const RenderResult result = render_for_test(scene, AccelKind::Bvh, spec, 777);
    const GoldenVerdict v = compare_to_golden(spec, result, "mutation-other-seed", true);
    WARN("other seed: " << v.block.summary());
    CHECK(v.accepted());
}

TEST_CASE("golden mutation: flipped normals are rejected", "[image][golden][mutation]") {
    const GoldenSpec& spec = golden_spec("cornell-box");
    expect_rejected(spec, load_golden_scene(spec), "mutation-flipped-normals", PlantedDefect::FlippedNormals);
}

TEST_CASE("golden mutation: no ray offset (acne) is rejected", "[image][golden][mutation]") {
    const GoldenSpec& spec = golden_spec("cornell-box");
    expect_rejected(spec, load_golden_scene(spec), "mutation-no-ray-offset", PlantedDefect::NoRayOffset);
}

TEST_CASE("golden mutation: a light removed is rejected", "[image][golden][mutation]") {
    const GoldenSpec& spec = golden_spec("cornell-box");
    Scene scene = load_golden_scene(spec);
    scene.objects.erase(scene.objects.begin() + static_cast<std::ptrdiff_t>(object_named(scene, "light")));
    expect_rejected(spec, scene, "mutation-light-removed");
}

TEST_CASE("golden mutation: a material swapped is rejected", "[image][golden][mutation]") {
    // The short box takes the red wall's material and the red wall the white: a local change on
    // the box and a global one on the wall's colour bleeding.
    const GoldenSpec& spec = golden_spec("cornell-box");
    Scene scene = load_golden_scene(spec);
    std::swap(scene.objects[object_named(scene, "short box")].material,
              scene.objects[object_named(scene, "left wall")].material);
    expect_rejected(spec, scene, "mutation-material-swapped");
}

TEST_CASE("golden mutation: one object shifted by 3 pixels is rejected", "[image][golden][mutation]") {
    // The tall box moves along the camera's right vector by the width of 3 pixels at its depth.
    const GoldenSpec& spec = golden_spec("cornell-box");
    Scene scene = load_golden_scene(spec);
    Object& box = scene.objects[object_named(scene, "tall box")];
    const glm::vec3 centre = glm::vec3(box.transform.to_world * glm::vec4(std::get<collision::Aabb>(box.shape).center, 1.0f));
    const Camera& cam = scene.camera;
    const glm::vec3 forward = glm::normalize(cam.look_at - cam.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, cam.up));
    const float depth = glm::dot(centre - cam.position, forward);
    const float pixel = 2.0f * depth * std::tan(glm::radians(0.5f * cam.vfov_degrees)) / static_cast<float>(spec.height);
    box.transform = Transform::from_matrix(glm::translate(glm::mat4(1.0f), 3.0f * pixel * right) * box.transform.to_world);
    expect_rejected(spec, scene, "mutation-object-shifted");
}

TEST_CASE("golden mutation: motion ignored is rejected", "[image][golden][mutation][motion]") {
    // The rolling sphere rendered still at its shutter-open pose: what a renderer that dropped
    // motion would show, in one region of the motion golden.
    const GoldenSpec& spec = golden_spec("motion");
    Scene scene = load_golden_scene(spec);
    scene.objects[object_named(scene, "rolling sphere")].motion = Motion{};
    expect_rejected(spec, scene, "mutation-motion-ignored");
}

// The caustic golden is bdpt's picture: the path tracer's render of the same scene, black under
// the water but for a few fireflies, must not pass as it (the test is not blind to the caustic).
TEST_CASE("golden mutation: the caustic scene by the path tracer is rejected", "[image][golden][mutation]") {
    const GoldenSpec& spec = golden_spec("caustic");
    Scene scene = load_golden_scene(spec);
    scene.film.integrator = IntegratorKind::Path;
    expect_rejected(spec, scene, "mutation-caustic-path");
}

// The motion blur scene keys (scene/load_motion.hpp): what loads, and every bad input refused with
// one line naming the file and the JSON path.
#include <catch2/catch.hpp>

#include <string>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "motion_test_scenes.hpp"
#include "scene_load_error.hpp"
#include "scene_test_files.hpp"

using sweeptrace::InputError;
using sweeptrace::load_scene;
using sweeptrace::test::TempDir;

namespace {

std::string scene_with(const std::string& camera_extra, const std::string& object_extra,
                       const std::string& material = R"({ "type": "diffuse", "albedo": [0.5, 0.5, 0.5] })") {
    return R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0])" + camera_extra + R"( },
  "film": { "width": 8, "height": 6 }, "materials": { "m": )" + material + R"( },
  "objects": [ { "type": "quad", "corner": [-5, -1, -5], "edge_u": [0, 0, 10], "edge_v": [10, 0, 0], "material": "m" },
               { "type": "sphere", "radius": 1, "material": "m")" + object_extra + R"( } ] })";
}

// The shared check, and one line: a message must not spill over lines.
std::string one_line_error(const TempDir& dir, const std::string& text) {
    const std::string message = sweeptrace::test::load_error(dir, text);
    CHECK(message.find('\n') == std::string::npos);
    return message;
}

const char* const kShutter = R"(, "shutter": [0, 1])";
const char* const kClose = R"(, "motion": { "close": [{ "translate": [1, 0, 0] }] })";

}  // namespace

TEST_CASE("motion scene: shutter, close and keyframes load", "[motion][scene]") {
    TempDir dir;
    const auto a = load_scene(dir.write("a.json", scene_with(kShutter, kClose)));
    CHECK(a.camera.shutter);
    CHECK(a.camera.shutter_close == 1.0f);
    REQUIRE(a.objects[1].motion.moving());
    CHECK(a.objects[1].motion.keys.size() == 2);
    CHECK(a.objects[1].motion.translation_only);
    CHECK_FALSE(a.objects[0].motion.moving());
    const auto b = load_scene(dir.write("b.json", scene_with(kShutter, R"(, "motion": { "keyframes": [
        [{ "translate": [0, 0, 0] }], [{ "rotate": { "axis": [0, 1, 0], "degrees": 90 } }], [{ "scale": 2 }] ] })")));
    REQUIRE(b.objects[1].motion.keys.size() == 3);
    CHECK(b.objects[1].transform.to_world == b.objects[1].motion.keys[0].to_world);
    // The shipped-style scene with every kind of motion, a mesh included.
    const auto c = sweeptrace::test::load_motion_scene(dir, 16, 12);
    std::size_t moving = 0;
    for (const auto& o : c.objects) moving += o.motion.moving() ? 1 : 0;
    CHECK(moving == 4);
}

TEST_CASE("motion scene: bad input names the key", "[motion][scene][errors]") {
    TempDir dir;
    CHECK_THAT(one_line_error(dir, scene_with(R"(, "shutter": [1, 0])", "")),
               Catch::Contains("camera.shutter") && Catch::Contains("open (1) is after close (0)"));
    CHECK_THAT(one_line_error(dir, scene_with(R"(, "shutter": [0])", "")), Catch::Contains("camera.shutter") && Catch::Contains("[open, close]"));
    CHECK_THAT(one_line_error(dir, scene_with(R"(, "shutter": [0, 1e39])", "")), Catch::Contains("camera.shutter[1]"));
    CHECK_THAT(one_line_error(dir, scene_with("", kClose)),
               Catch::Contains("objects[1].motion") && Catch::Contains("no shutter"));
    CHECK_THAT(one_line_error(dir, scene_with("", R"(, "motion": { "close": [] })")),  // a still pose, still no shutter
               Catch::Contains("objects[1].motion") && Catch::Contains("no shutter"));
    CHECK_THAT(one_line_error(dir, scene_with(kShutter, R"(, "motion": { "close": [{ "translate": [1e39, 0, 0] }] })")),
               Catch::Contains("objects[1].motion.close[0].translate[0]"));
    CHECK_THAT(one_line_error(dir, scene_with(kShutter, R"(, "motion": { "keyframes": [[{ "translate": [1, 0, 0] }]] })")),
               Catch::Contains("objects[1].motion.keyframes") && Catch::Contains("2 to 129") && Catch::Contains("got 1"));
    std::string many = R"(, "motion": { "keyframes": [)";
    for (int i = 0; i < 130; ++i) many += std::string(i ? "," : "") + R"([{ "translate": [0, 0, 0] }])";
    CHECK_THAT(one_line_error(dir, scene_with(kShutter, many + "] }")), Catch::Contains("got 130"));
    CHECK_THAT(one_line_error(dir, scene_with(kShutter, R"(, "transform": [{ "scale": 2 }], "motion": { "keyframes": [[], []] })")),
               Catch::Contains("objects[1].transform") && Catch::Contains("keyframes[0] is the pose at shutter open"));
    CHECK_THAT(one_line_error(dir, scene_with(kShutter, R"(, "motion": { "close": [], "keyframes": [[], []] })")),
               Catch::Contains("objects[1].motion") && Catch::Contains("exactly one"));
    CHECK_THAT(one_line_error(dir, scene_with(kShutter, R"(, "motion": { "closed": [] })")), Catch::Contains("objects[1].motion.closed"));
    CHECK_THAT(one_line_error(dir, scene_with(kShutter, R"(, "motion": { "close": [{ "scale": 0 }] })")),
               Catch::Contains("objects[1].motion.close[0].scale"));
    CHECK_THAT(one_line_error(dir, scene_with(kShutter, kClose, R"({ "type": "emissive", "emission": [1, 1, 1] })")),
               Catch::Contains("objects[1].motion") && Catch::Contains("moving lights are not supported"));
}

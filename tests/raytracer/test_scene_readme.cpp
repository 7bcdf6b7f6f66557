// The examples in scenes/README.md are real: each JSON block there loads (wrapped into a whole
// scene where it is a fragment), so the documentation cannot drift from the loader.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "raytracer/image/image.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/text_file.hpp"
#include "scene_test_files.hpp"
#include "vdb_test_files.hpp"

namespace {

std::vector<std::string> json_blocks(const std::string& markdown) {
    std::vector<std::string> blocks;
    const std::string open = "```json\n", close = "```";
    for (std::size_t at = markdown.find(open); at != std::string::npos; at = markdown.find(open, at)) {
        const std::size_t begin = at + open.size();
        const std::size_t end = markdown.find(close, begin);
        REQUIRE(end != std::string::npos);
        blocks.push_back(markdown.substr(begin, end - begin));
        at = end + close.size();
    }
    return blocks;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

TEST_CASE("scenes README: every JSON example loads", "[scene][docs]") {
    const std::filesystem::path scenes = std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes";
    const auto blocks = json_blocks(sweeptrace::read_text_file(scenes / "README.md", "README"));
    REQUIRE(blocks.size() >= 4);

    sweeptrace::test::TempDir dir;
    dir.write("meshes/torus_knot.obj", sweeptrace::read_text_file(scenes / "meshes" / "torus_knot.obj", "mesh"));
    // The environment example's map: 4 x 2 uncompressed RGBE texels of 1.0.
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
    for (int i = 0; i < 8; ++i) hdr += std::string{char(128), char(128), char(128), char(129)};
    dir.write("sky.hdr", hdr);
    sweeptrace::write_image(sweeptrace::Image(2, 2), dir.path() / "pbrt_sky.exr");  // the equal-area example's: square
    sweeptrace::write_image(sweeptrace::Image(2, 2), dir.path() / "wood.png");  // the image texture example's file
    sweeptrace::test::write_small_vdb(dir.path() / "cloud.vdb");                   // the vdb medium example's
    std::string materials;
    for (const std::string& b : blocks)
        if (starts_with(b, "\"materials\"")) materials = b;
    REQUIRE_FALSE(materials.empty());
    const std::string head = R"({ "camera": { "position": [0, 1, 5], "look_at": [0, 1, 0] },
                                  "film": { "width": 4, "height": 4 }, )";

    int loaded = 0;
    for (const std::string& b : blocks) {
        INFO(b);
        std::string scene;
        if (starts_with(b, "{ \"type\""))  // one object
            scene = head + materials + R"(, "objects": [)" + b + "]}";
        else if (starts_with(b, "{"))
            scene = b;
        else if (starts_with(b, "\"materials\""))
            scene = head + b + R"(, "objects": [] })";
        else if (starts_with(b, "\"objects\""))
            scene = head + materials + ", " + b + "}";
        else if (starts_with(b, "\"film\""))
            scene = R"({ "camera": { "position": [0, 1, 5], "look_at": [0, 1, 0] }, )" + b + ", " + materials +
                    R"(, "objects": [] })";
        else if (starts_with(b, "\"albedo\""))
            scene = head + R"("materials": { "t": { "type": "diffuse", )" + b +
                    R"( } }, "objects": [{ "type": "quad", "corner": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [0, 1, 0], "material": "t" }] })";
        else if (starts_with(b, "\"background\""))
            scene = head + materials + R"(, "objects": [], )" + b + "}";
        else if (starts_with(b, "\"lights\""))
            scene = head + materials + R"(, "objects": [], )" + b + "}";
        else if (starts_with(b, "\"media\""))
            scene = head + materials + R"(, "objects": [], )" + b + "}";
        else if (starts_with(b, "\"transform\""))
            scene = head + materials + R"(, "objects": [{ "type": "sphere", "radius": 1, "material": "chalk", )" + b + "}]}";
        else
            FAIL("unrecognised example block");
        const auto result = sweeptrace::load_scene(dir.write("example.json", scene));
        ++loaded;
        if (starts_with(b, "\"objects\"")) CHECK(result.objects.size() == 10);
    }
    CHECK(loaded == static_cast<int>(blocks.size()));
}

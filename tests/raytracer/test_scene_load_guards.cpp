// Issue 32: what a scene load promises beyond each reader's own checks. The files it read are
// listed by the readers themselves (read_files.hpp: what the command line protects from being
// overwritten); its memory is one budget (load_budget.hpp); the pbrt importer accepts pbrt-v4's
// seeds, escapes what it echoes and shares an area light's parameters instead of copying them.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"
#include "raytracer/scene/pbrt/pbrt_materials.hpp"
#include "raytracer/scene/pbrt/pbrt_parser.hpp"
#include "scene_test_files.hpp"

namespace {

using sweeptrace::test::TempDir;

bool lists(const std::vector<std::filesystem::path>& files, const std::filesystem::path& file) {
    std::error_code ec;
    return std::any_of(files.begin(), files.end(), [&](const std::filesystem::path& f) { return std::filesystem::equivalent(f, file, ec); });
}

void write_png(const std::filesystem::path& file, int side) {
    sweeptrace::Image image(side, side);
    for (glm::vec3& p : image.pixels) p = glm::vec3(0.5f);
    sweeptrace::write_image(image, file);
}

const char* kPbrtHead = "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n";

}  // namespace

TEST_CASE("scene load: the files read are listed by the readers (JSON, OBJ, MTL, textures, environment)", "[scene][issue32]") {
    TempDir dir;
    write_png(dir.path() / "tex.png", 4);
    write_png(dir.path() / "nrm.png", 4);
    sweeptrace::Image env(4, 2);
    sweeptrace::write_image(env, dir.path() / "env.pfm");
    dir.write("tri.obj", "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    dir.write("tri.mtl", "newmtl a\nKd 0.5 0.5 0.5\n");
    dir.write("unread.png", "not read by the scene");
    const auto scene_file = dir.write("s.json", R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "film": {"width": 4, "height": 4},
      "background": {"environment": {"file": "env.pfm"}},
      "materials": {"m": {"type": "diffuse", "albedo": {"image": {"file": "tex.png"}}, "normal_map": {"image": {"file": "nrm.png"}}}},
      "objects": [{"type": "sphere", "radius": 1, "material": "m"}, {"type": "mesh", "file": "tri.obj"}]})");
    const sweeptrace::Scene scene = sweeptrace::load_scene(scene_file);
    for (const char* name : {"s.json", "tex.png", "nrm.png", "env.pfm", "tri.obj", "tri.mtl"}) {
        INFO(name);
        CHECK(lists(scene.input_files, dir.path() / name));
    }
    CHECK_FALSE(lists(scene.input_files, dir.path() / "unread.png"));
}

TEST_CASE("scene load: a pbrt scene lists its Includes, spectrum files and image textures", "[scene][pbrt][issue32]") {
    TempDir dir;
    write_png(dir.path() / "tex.png", 4);
    dir.write("inc.pbrt", "Shape \"sphere\"\n");
    dir.write("eta.spd", "400 1.5\n800 1.5\n");
    dir.write("k.spd", "400 3\n800 3\n");
    const auto file = dir.write("s.pbrt", std::string(kPbrtHead) + "WorldBegin\nInclude \"inc.pbrt\"\n"
                                          "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"tex.png\"\n"
                                          "Material \"diffuse\" \"texture reflectance\" \"t\"\nShape \"sphere\"\n"
                                          "Material \"conductor\" \"spectrum eta\" \"eta.spd\" \"spectrum k\" \"k.spd\"\nShape \"sphere\"\n");
    std::vector<std::string> warnings;
    const sweeptrace::Scene scene = sweeptrace::load_pbrt_scene(file, false, warnings);
    for (const char* name : {"s.pbrt", "inc.pbrt", "eta.spd", "k.spd", "tex.png"}) {
        INFO(name);
        CHECK(lists(scene.input_files, dir.path() / name));
    }
    const sweeptrace::PbrtConversion c = sweeptrace::convert_pbrt(file, dir.path() / "out.json", false, true);
    CHECK(lists(c.input_files, dir.path() / "tex.png"));
    CHECK(lists(c.input_files, dir.path() / "k.spd"));
}

TEST_CASE("load budget: images are charged as decoded, and the charge past the limit is refused with the file", "[scene][issue32]") {
    TempDir dir;
    write_png(dir.path() / "a.png", 64);
    write_png(dir.path() / "b.png", 64);
    const auto file = dir.write("s.json", R"({
      "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "film": {"width": 4, "height": 4},
      "materials": {"a": {"type": "diffuse", "albedo": {"image": {"file": "a.png"}}},
                    "b": {"type": "diffuse", "albedo": {"image": {"file": "b.png"}}}},
      "objects": [{"type": "sphere", "radius": 1, "material": "a"}, {"type": "sphere", "radius": 1, "center": [3, 0, 0], "material": "b"}]})");
    const std::uint64_t one = 64 * 64 * sizeof(glm::vec3);  // 48 kB decoded
    {
        sweeptrace::set_load_memory_limit(one * 2);
        sweeptrace::LoadBudgetScope budget;  // the load joins it, so what it charged can be read
        (void)sweeptrace::load_scene(file);
        CHECK(sweeptrace::load_memory_charged() == one * 2);
    }
    sweeptrace::set_load_memory_limit(one * 2 - 1);
    try {
        (void)sweeptrace::load_scene(file);
        FAIL("a load over its budget was not refused");
    } catch (const sweeptrace::InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("b.png: PNG image 64x64 needs 49 kB") && Catch::Contains("over the load budget of 98 kB (--max-memory)"));
    }
    sweeptrace::set_load_memory_limit(std::nullopt);
    CHECK(sweeptrace::load_memory_charged() == 0);  // outside a load nothing is counted
}

TEST_CASE("pbrt: an AreaLightSource's parameters are shared by the levels, shapes and instances below it, not copied",
          "[pbrt][issue32]") {
    TempDir dir;
    // Copied, a 4 MB parameter cost 4 MB per AttributeBegin level, Shape and ObjectInstance.
    const std::string area = "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"float junk\" [1 2 3]\n";
    const auto file = dir.write("s.pbrt", std::string(kPbrtHead) + "WorldBegin\nObjectBegin \"o\"\n" + area +
                                              "Shape \"sphere\"\nObjectEnd\n" + area +
                                              "AttributeBegin\nAttributeBegin\nShape \"sphere\"\nAttributeEnd\nShape \"sphere\"\n"
                                              "AttributeEnd\nObjectInstance \"o\"\nObjectInstance \"o\"\n");
    sweeptrace::pbrt::Diagnostics diag(false);
    const sweeptrace::pbrt::FileNames files(file, dir.path());
    sweeptrace::pbrt::MaterialTranslator materials(files, diag);
    const sweeptrace::pbrt::PbrtScene scene = sweeptrace::pbrt::parse_pbrt(file, materials, files, diag);
    REQUIRE(scene.shapes.size() == 4);
    REQUIRE(scene.shapes[0].area_light);
    CHECK(scene.shapes[1].area_light.get() == scene.shapes[0].area_light.get());  // two levels apart
    CHECK(scene.shapes[2].area_light.get() == scene.shapes[3].area_light.get());  // two instances of one shape
    CHECK(scene.shapes[2].area_light.get() != scene.shapes[0].area_light.get());  // the object's own light
}

TEST_CASE("pbrt: the sampler's seed is any integer, as in pbrt-v4", "[pbrt][issue32]") {
    TempDir dir;
    for (const auto& [written, seed] : std::vector<std::pair<std::string, std::uint64_t>>{{"5", 5}, {"0", 0}, {"-1", ~std::uint64_t{0}}}) {
        INFO(written);
        const auto file = dir.write("s.pbrt", std::string(kPbrtHead) + "Sampler \"zsobol\" \"integer seed\" " + written +
                                                  "\nWorldBegin\nShape \"sphere\"\n");
        std::vector<std::string> warnings;
        CHECK(sweeptrace::load_pbrt_scene(file, true, warnings).seed == seed);
    }
}

TEST_CASE("pbrt: control characters from the file are escaped in warnings and errors, and TransformBegin has AttributeBegin's depth limit",
          "[pbrt][issue32]") {
    TempDir dir;
    const auto file = dir.write("s.pbrt", std::string(kPbrtHead) + "WorldBegin\nShape \"x\x1b[31m\\nsweeptrace: error: forged\"\nShape \"sphere\"\n");
    std::vector<std::string> warnings;
    (void)sweeptrace::load_pbrt_scene(file, false, warnings);
    REQUIRE(!warnings.empty());
    CHECK_THAT(warnings.front(), Catch::Contains("x\\x1b[31m\\nsweeptrace: error: forged"));
    for (const std::string& w : warnings) CHECK(std::none_of(w.begin(), w.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }));
    CHECK_THROWS_WITH(sweeptrace::load_pbrt_scene(file, true, warnings), Catch::Contains("x\\x1b[31m\\nsweeptrace"));

    std::string deep = std::string(kPbrtHead) + "WorldBegin\n";
    for (int i = 0; i < 4097; ++i) deep += "TransformBegin\n";
    const auto deep_file = dir.write("deep.pbrt", deep);
    CHECK_THROWS_WITH(sweeptrace::load_pbrt_scene(deep_file, false, warnings),
                      Catch::Contains("deep.pbrt:4099: TransformBegin nested more than 4096 deep"));
}

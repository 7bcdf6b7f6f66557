// pbrt-v4's participating media through the importer (scene/pbrt/pbrt_media.cpp): MakeNamedMedium,
// MediumInterface on shapes and the camera, the "interface" material; and the two shared scenes
// that have media import them with no media warning.
#include <catch2/catch.hpp>

#include <filesystem>

#include "pbrt_test_support.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/render/media/media_nesting.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"

using namespace sweeptrace;
using namespace sweeptrace::test;
using nlohmann::json;

TEST_CASE("pbrt media: MakeNamedMedium, MediumInterface and the interface material become our media keys", "[pbrt][media]") {
    const TempDir dir;
    const auto c = convert_text(dir,
                                "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.1 0.2 0.3] "
                                "\"rgb sigma_s\" [1 1 1] \"float scale\" 2 \"float g\" 0.5\n"
                                "MediumInterface \"\" \"fog\"\nCamera \"perspective\"\nWorldBegin\n"
                                "Translate 1 0 0\nMakeNamedMedium \"smoke\" \"string type\" \"uniformgrid\" \"integer nx\" 2 "
                                "\"float density\" [0 1]\nIdentity\n"
                                "AttributeBegin\nMediumInterface \"smoke\" \"fog\"\nMaterial \"interface\"\nShape \"sphere\"\nAttributeEnd\n"
                                "AttributeBegin\nMediumInterface \"\" \"\"\nMaterial \"interface\"\nShape \"sphere\" \"float radius\" 3\nAttributeEnd\n"
                                "AttributeBegin\nMediumInterface \"fog\" \"fog\"\nMaterial \"diffuse\"\nShape \"sphere\" \"float radius\" 5\nAttributeEnd\n");
    CHECK(c.warnings.empty());
    const json& media = c.doc["media"];
    CHECK(media["fog"]["type"] == "homogeneous");
    CHECK(media["fog"]["scale"] == 2.0);
    CHECK(media["fog"]["g"] == 0.5);
    CHECK(media["smoke"]["type"] == "grid");
    CHECK(media["smoke"]["size"] == json({2, 1, 1}));
    CHECK(media["smoke"]["transform"] == json::array({{{"translate", {1.0, 0.0, 0.0}}}}));
    CHECK(c.doc["camera"]["medium"] == "fog");
    // The interface sphere bounds smoke inside fog; the one bounding nothing is left out; a
    // diffuse sphere with fog on both sides is no boundary.
    REQUIRE(c.doc["objects"].size() == 2);
    const json& ball = c.doc["objects"][0];
    CHECK(ball["inside"] == "smoke");
    CHECK(ball["outside"] == "fog");
    CHECK(c.doc["materials"][ball["material"].get<std::string>()]["type"] == "interface");
    CHECK_FALSE(c.doc["objects"][1].contains("inside"));
    CHECK_FALSE(c.doc["objects"][1].contains("outside"));
}

TEST_CASE("pbrt media: a uniformgrid's Le and per-voxel Lescale become its emission and emission_scale", "[pbrt][media]") {
    const TempDir dir;
    const std::string grid = "MakeNamedMedium \"glow\" \"string type\" \"uniformgrid\" \"integer nx\" 2 \"float density\" [1 1] ";
    const auto c = convert_text(dir, world_with(grid + "\"rgb Le\" [1 1 1] \"float Lescale\" [0.5 2]\n"
                                                "MediumInterface \"glow\" \"\"\nMaterial \"interface\"\nShape \"sphere\""));
    CHECK(c.warnings.empty());
    const json& glow = c.doc["media"]["glow"];
    REQUIRE(glow.contains("emission"));
    CHECK(glow["emission"][0].get<double>() > 0.0);  // an illuminant, normalized as pbrt-v4's lights and homogeneous Le
    CHECK(glow["emission_scale"] == json({0.5, 2.0}));
    // Without Lescale the emission is uniform; a count other than the grid's is refused at its line.
    CHECK_FALSE(convert_text(dir, world_with(grid + "\"rgb Le\" [1 1 1]"))
                    .doc["media"]["glow"].contains("emission_scale"));
    CHECK_THROWS_WITH(convert_text(dir, world_with(grid + "\"rgb Le\" [1 1 1] \"float Lescale\" [1 2 3]")),
                      Catch::Contains("3 \"Lescale\" values, but the grid has 2"));
    // A blackbody "temperature" grid has no RGB counterpart: warned, not emitting.
    const auto t = convert_text(dir, world_with(grid + "\"float temperature\" [1000 2000]"));
    CHECK(has_warning(t.warnings, "blackbody emission from \"temperature\" is not imported"));
    CHECK_FALSE(t.doc["media"]["glow"].contains("emission"));
}

TEST_CASE("pbrt media: an unsupported medium is warned with what is lost and is vacuum where named", "[pbrt][media]") {
    const TempDir dir;
    const auto c = convert_text(dir, world_with("MakeNamedMedium \"cloud\" \"string type\" \"cloud\" \"float density\" 2\n"
                                                "MediumInterface \"cloud\" \"\"\nShape \"sphere\""));
    CHECK(has_warning(c.warnings, "MakeNamedMedium \"cloud\": medium type \"cloud\" is not supported"));
    CHECK_FALSE(c.doc.contains("media"));
    CHECK_FALSE(c.doc["objects"][0].contains("inside"));
}

TEST_CASE("pbrt media: volumetric-caustic and staircase2 import with their media, no media warning, and nest", "[pbrt][media]") {
    const std::filesystem::path shared = std::filesystem::path(SWEEPTRACE_SHARED_DIR) / "bitterli";
    for (const char* name : {"volumetric-caustic", "staircase2"}) {
        const std::filesystem::path file = shared / name / "scene-v4.pbrt";
        if (!std::filesystem::is_regular_file(file)) {
            WARN("SKIPPED: needs " << file);
            continue;
        }
        INFO(name);
        std::vector<std::string> warnings;
        const Scene s = load_pbrt_scene(file, false, warnings);
        for (const std::string& w : warnings) CHECK(w.find("medium") == std::string::npos);
        REQUIRE(s.media.size() == 1);
        int bounded = 0;
        for (const Object& o : s.objects) bounded += o.media.transition();
        CHECK(bounded > 0);
        CHECK(uses_media(s));
        // Their boundaries agree with each other and with the camera (media_nesting.hpp).
        CHECK_NOTHROW(check_media_nesting(s, *make_accel(AccelKind::Bvh, s)));
    }
}

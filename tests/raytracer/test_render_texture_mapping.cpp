// A texture's uv mapping and value adjustments (scene.hpp: Texture; pbrt-v4's uv mapping and image
// texture): a lookup at uv reads the pattern at (su u + du, sv v + dv); an image's value is scaled,
// inverted and kept in the parameter's range; an 8-bit image's "encoding" overrides the reading
// its use implies. And the pbrt importer's imagemap, scale and checkerboard textures as these keys.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "pbrt_test_support.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/render/materials/texture.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_load_error.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using sweeptrace::test::TempDir;
using nlohmann::json;

namespace {

// A 4 x 2 image whose texels all differ (texel (i, j) = 0.1 + 0.1 i + 0.4 j, grey).
std::shared_ptr<const Image> ramp_image() {
    auto img = std::make_shared<Image>(4, 2);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 4; ++i) img->at(i, j) = glm::vec3(0.1f + 0.1f * i + 0.4f * j);
    return img;
}

std::string mapping_scene(const std::string& albedo) {
    return R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "film": { "width": 4, "height": 4 },
        "materials": { "m": { "type": "diffuse", "albedo": )" + albedo + R"( } },
        "objects": [ { "type": "quad", "corner": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [0, 1, 0], "material": "m" } ] })";
}

}  // namespace

TEST_CASE("texture mapping: a lookup reads the pattern at (su u + du, sv v + dv)", "[render][texture]") {
    Texture plain;
    plain.kind = Texture::Kind::Image;
    plain.image = ramp_image();
    Texture mapped = plain;
    mapped.uv_scale = {2.0f, -1.0f};  // pbrt's vscale -1 flips the image
    mapped.uv_offset = {0.25f, 0.5f};
    for (const glm::vec2 uv : {glm::vec2(0.1f, 0.2f), glm::vec2(0.3f, 0.9f), glm::vec2(0.45f, 0.6f), glm::vec2(-0.7f, 1.3f)}) {
        const glm::vec2 at(2.0f * uv.x + 0.25f, -uv.y + 0.5f);
        CHECK(eval_texture(mapped, uv) == eval_texture(plain, at));
    }
    // A checker: scale 1 with uv_scale (2, 1) has two squares along u per one along v.
    Texture checker;
    checker.scale = 1.0f;
    checker.a = glm::vec3(1.0f);
    checker.b = glm::vec3(0.0f);
    checker.uv_scale = {2.0f, 1.0f};
    CHECK(eval_texture(checker, {0.25f, 0.25f}) == glm::vec3(1.0f));
    CHECK(eval_texture(checker, {0.75f, 0.25f}) == glm::vec3(0.0f));
    CHECK(eval_texture(checker, {0.25f, 0.75f}) == glm::vec3(1.0f));
}

TEST_CASE("texture mapping: multiply, then invert, then the parameter's range", "[render][texture]") {
    Texture t;
    t.kind = Texture::Kind::Image;
    t.image = ramp_image();
    const glm::vec2 uv(0.375f, 0.75f);  // texel (1, 0)'s centre: 0.2
    CHECK(eval_texture(t, uv) == glm::vec3(0.2f));
    t.multiply = glm::vec3(2.0f, 3.0f, 6.0f);
    CHECK(eval_texture(t, uv) == glm::vec3(0.4f, 0.6f, 1.0f));  // 6 x 0.2 = 1.2, an albedo keeps 1
    t.invert = true;
    CHECK(eval_texture(t, uv).x == Approx(0.6f));
    CHECK(eval_texture(t, uv).z == 0.0f);  // 1 - 1.2 < 0: kept at 0
    t.invert = false;
    t.max_value = std::numeric_limits<float>::infinity();  // an emission is not limited to 1
    CHECK(eval_texture(t, uv).z == Approx(1.2f));
}

TEST_CASE("texture mapping: scene keys, their errors, and the encoding of an 8-bit image", "[scene][texture]") {
    const TempDir dir;
    Image img(2, 1);
    img.at(0, 0) = glm::vec3(srgb_decode(64.0f / 255.0f));
    img.at(1, 0) = glm::vec3(srgb_decode(192.0f / 255.0f));
    write_image(img, dir.path() / "grey.png");
    const Scene s = load_scene(dir.write("s.json", mapping_scene(R"({ "image": { "file": "grey.png", "uv_scale": [2, 3], "uv_offset": [0.5, -1],
        "multiply": [0.5, 1, 2], "invert": true, "encoding": "linear" } })")));
    const Texture& t = s.textures.at(0);
    CHECK(t.uv_scale == glm::vec2(2.0f, 3.0f));
    CHECK(t.uv_offset == glm::vec2(0.5f, -1.0f));
    CHECK(t.multiply == glm::vec3(0.5f, 1.0f, 2.0f));
    CHECK(t.invert);
    // "linear": an albedo from a .png reads its stored codes, not their sRGB decoding.
    CHECK(t.image->pixels[0] == glm::vec3(64.0f / 255.0f));
    const Scene d = load_scene(dir.write("d.json", R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "film": { "width": 4, "height": 4 },
        "materials": { "m": { "type": "metal", "roughness": { "image": { "file": "grey.png", "encoding": "sRGB" } } } }, "objects": [] })"));
    CHECK(d.textures.at(0).image->pixels[1] == img.at(1, 0));  // a roughness read sRGB-decoded
    using sweeptrace::test::load_error;
    CHECK_THAT(load_error(dir, mapping_scene(R"({ "image": { "file": "grey.png", "uv_scale": [0, 1] } })")),
               Catch::Contains("materials.m.albedo.image.uv_scale[0]: must not be 0"));
    CHECK_THAT(load_error(dir, mapping_scene(R"({ "image": { "file": "grey.png", "uv_offset": [1] } })")),
               Catch::Contains("materials.m.albedo.image.uv_offset: must be an array of 2 numbers"));
    // A negative factor: an albedo keeps 0, a bump map's height turns over (pbrt's displacement).
    const Scene neg = load_scene(dir.write("n.json", R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "film": { "width": 4, "height": 4 },
        "materials": { "m": { "type": "diffuse", "albedo": { "image": { "file": "grey.png", "multiply": -1 } },
                              "bump_map": { "image": { "file": "grey.png", "multiply": -2 } } } }, "objects": [] })"));
    CHECK(eval_texture(neg.textures.at(0), {0.25f, 0.5f}) == glm::vec3(0.0f));
    CHECK(eval_texture(neg.textures.at(1), {0.25f, 0.5f}).x == Approx(-2.0f * 64.0f / 255.0f));
    CHECK_THAT(load_error(dir, mapping_scene(R"({ "image": { "file": "grey.png", "multiply": "x" } })")),
               Catch::Contains("materials.m.albedo.image.multiply"));
    CHECK_THAT(load_error(dir, mapping_scene(R"({ "image": { "file": "grey.png", "encoding": "gamma" } })")),
               Catch::Contains("materials.m.albedo.image.encoding: must be \"sRGB\" or \"linear\""));
    CHECK_THAT(load_error(dir, mapping_scene(R"([0.5, 0.5, 0.5], "emission": { "image": { "file": "grey.png", "invert": true } })")),
               Catch::Contains("materials.m.emission.image.invert: an emission texture cannot be inverted"));
    CHECK_THAT(load_error(dir, mapping_scene(R"({ "checker": { "uv_scale": [1, 0] } })")),
               Catch::Contains("materials.m.albedo.checker.uv_scale[1]: must not be 0"));
}

TEST_CASE("pbrt textures: imagemap scale, invert, uscale..vdelta, encoding, scale of an image, checkerboard's uv", "[pbrt][texture]") {
    const TempDir dir;
    write_image(Image(4, 4), dir.path() / "t.png");
    write_image(Image(4, 4), dir.path() / "t.exr");
    const auto c = sweeptrace::test::convert_text(dir,
        "WorldBegin\n"
        "Texture \"a\" \"spectrum\" \"imagemap\" \"string filename\" \"t.png\" \"float scale\" 0.5 \"bool invert\" true\n"
        "  \"float uscale\" 4 \"float vscale\" -1 \"float udelta\" 0.25 \"float vdelta\" 0\n"
        "Texture \"r\" \"float\" \"imagemap\" \"string filename\" \"t.png\"\n"
        "Texture \"lin\" \"spectrum\" \"imagemap\" \"string filename\" \"t.png\" \"string encoding\" \"linear\"\n"
        "Texture \"s\" \"spectrum\" \"scale\" \"texture tex\" \"lin\" \"float scale\" 0.64\n"
        "Texture \"k\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 2 \"float vdelta\" 0.5\n"
        "Material \"diffuse\" \"texture reflectance\" \"a\"\nShape \"sphere\"\n"
        "Material \"conductor\" \"texture roughness\" \"r\"\nShape \"sphere\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"s\"\nShape \"sphere\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"k\"\nShape \"sphere\"\n");
    // The one approximation here: pbrt remaps a roughness texture's values (not ours to do).
    REQUIRE(c.warnings.size() == 1);
    CHECK(c.warnings[0].find("a roughness texture is used as our roughness") != std::string::npos);
    auto mat = [&](int i) { return c.doc["materials"][c.doc["objects"][i]["material"].get<std::string>()]; };
    CHECK(mat(0)["albedo"]["image"] == json({{"file", "t.png"}, {"multiply", {0.5, 0.5, 0.5}}, {"invert", true},
                                            {"uv_scale", {4.0, -1.0}}, {"uv_offset", {0.25, 0.0}}}));
    // pbrt reads an 8-bit image as sRGB unless told otherwise, for numbers too.
    CHECK(mat(1)["roughness"]["image"]["encoding"] == "sRGB");
    CHECK(mat(2)["albedo"]["image"] == json({{"file", "t.png"}, {"encoding", "linear"}, {"multiply", {0.64, 0.64, 0.64}}}));
    CHECK(mat(3)["albedo"]["checker"] == json({{"a", {1.0, 1.0, 1.0}}, {"b", {0.0, 0.0, 0.0}}, {"scale", 1.0},
                                              {"uv_scale", {8.0, 2.0}}, {"uv_offset", {0.0, 0.5}}}));
    // And the whole of it loads: the JSON keys are the loader's.
    std::vector<std::string> warnings;
    CHECK_NOTHROW(load_pbrt_scene(dir.path() / "scene.pbrt", false, warnings));
}

TEST_CASE("pbrt materials: \"displacement\" is our bump map, \"normalmap\" our normal map", "[pbrt][texture]") {
    const TempDir dir;
    write_image(Image(4, 4), dir.path() / "bump.png");
    write_image(Image(4, 4), dir.path() / "n.png");
    const auto c = sweeptrace::test::convert_text(dir,
        "WorldBegin\n"
        "Texture \"b\" \"float\" \"imagemap\" \"string filename\" \"bump.png\" \"float scale\" -0.01\n"
        "Texture \"k\" \"float\" \"checkerboard\"\n"
        "Material \"coateddiffuse\" \"texture displacement\" \"b\" \"string normalmap\" \"n.png\"\nShape \"sphere\"\n"
        "Material \"diffuse\" \"float displacement\" 0.5\nShape \"sphere\"\n"
        "Material \"diffuse\" \"texture displacement\" \"k\"\nShape \"sphere\"\n");
    auto mat = [&](int i) { return c.doc["materials"][c.doc["objects"][i]["material"].get<std::string>()]; };
    // pbrt decodes the 8-bit height as sRGB and multiplies it by its scale, in world units.
    CHECK(mat(0)["bump_map"] == json({{"image", {{"file", "bump.png"}, {"encoding", "sRGB"}, {"multiply", {-0.01, -0.01, -0.01}}}}}));
    CHECK(mat(0)["normal_map"] == json({{"image", {{"file", "n.png"}}}}));
    CHECK_FALSE(mat(1).contains("bump_map"));  // a constant height tilts nothing
    CHECK_FALSE(mat(2).contains("bump_map"));
    REQUIRE(c.warnings.size() == 1);
    CHECK(c.warnings[0].find("a checker has no slope") != std::string::npos);
    std::vector<std::string> warnings;
    const Scene s = load_pbrt_scene(dir.path() / "scene.pbrt", false, warnings);
    CHECK(s.materials.at(s.objects.at(0).material).bump_texture >= 0);
    CHECK(s.materials.at(s.objects.at(0).material).normal_texture >= 0);
}

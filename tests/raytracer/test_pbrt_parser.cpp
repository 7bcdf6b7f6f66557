// The pbrt-v4 importer's lexical and parameter-list levels (scene/pbrt/pbrt_tokenizer.hpp,
// scene/pbrt/pbrt_params.hpp), and the structure directives: every malformed input is an InputError
// naming file:line.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "pbrt_test_support.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/pbrt/pbrt_params.hpp"
#include "raytracer/scene/pbrt/pbrt_spectra.hpp"
#include "raytracer/scene/pbrt/pbrt_tokenizer.hpp"

using namespace sweeptrace;
using namespace sweeptrace::pbrt;
using sweeptrace::test::convert_text;
using sweeptrace::test::TempDir;
using sweeptrace::test::world_with;

namespace {

Where here() { return {std::make_shared<const std::string>("t.pbrt"), 0}; }

ParamList params_of(const std::string& text) {
    const Diagnostics d(false);
    const std::vector<Token> tokens = tokenize(text, here(), d);
    std::size_t pos = 0;
    ParamList p = parse_params(tokens, pos, here(), d);
    REQUIRE(pos == tokens.size());
    return p;
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("pbrt tokenizer: words, strings with escapes, brackets, comments, lines", "[pbrt]") {
    const Diagnostics d(false);
    const auto t = tokenize("Shape \"tri\\\"angle\" # a comment \"not a string\"\n[1 -2.5e3]\n\"a\\\\b\"", here(), d);
    REQUIRE(t.size() == 7);
    CHECK(t[0].text == "Shape");
    CHECK(t[0].kind == Token::Kind::Word);
    CHECK(t[1].text == "tri\"angle");
    CHECK(t[1].kind == Token::Kind::String);
    CHECK(t[2].kind == Token::Kind::Open);
    CHECK(t[2].line == 2);
    CHECK(t[3].text == "1");
    CHECK(t[4].text == "-2.5e3");
    CHECK(t[5].kind == Token::Kind::Close);
    CHECK(t[6].text == "a\\b");
    CHECK(t[6].line == 3);
    const auto u = tokenize("\"a\\\\b\"", here(), d);
    CHECK(u[0].text == "a\\b");
}

TEST_CASE("pbrt tokenizer: an unterminated string names its line", "[pbrt]") {
    const Diagnostics d(false);
    CHECK_THAT(error_of([&] { tokenize("Shape\n\"sphere\n\"", here(), d); }),
               Catch::StartsWith("t.pbrt:2: unterminated string"));
    CHECK_THAT(error_of([&] { tokenize(std::string("Shape \x01"), here(), d); }), Catch::Contains("control byte 1"));
}

TEST_CASE("pbrt parameters: every type, bracketed and bare", "[pbrt]") {
    const Diagnostics d(false);
    const ParamList p = params_of(
        "\"float radius\" 2.5 \"integer n\" [ 3 ] \"point3 P\" [ 0 0 0 1 2 3 ] \"normal N\" [0 0 1] "
        "\"rgb Kd\" [0.1 0.2 0.3] \"spectrum eta\" \"metal-Au-eta\" \"spectrum s\" [300 0.1 800 0.9] "
        "\"string filename\" \"a b.ply\" \"bool on\" true \"bool off\" \"false\" \"texture reflectance\" \"wood\" "
        "\"blackbody L\" 6500 \"point2 uv\" [0 0 1 1]");
    CHECK(p.get_float("radius", 0, d) == 2.5);
    CHECK(p.get_int("n", 0, d) == 3);
    CHECK(p.get_floats("P", d) == std::vector<double>{0, 0, 0, 1, 2, 3});
    CHECK(p.get_point3("N", d) == glm::dvec3(0, 0, 1));
    CHECK(p.find("N")->type == "normal3");  // pbrt-v3's "normal" is normal3
    CHECK(p.get_spectrum("Kd", d)->rgb == glm::dvec3(0.1, 0.2, 0.3));
    CHECK(p.get_spectrum("eta", d)->kind == SpectrumValue::Kind::Named);
    CHECK(p.get_spectrum("eta", d)->name == "metal-Au-eta");
    CHECK(p.get_spectrum("s", d)->kind == SpectrumValue::Kind::Sampled);
    CHECK(p.get_string("filename", "", d) == "a b.ply");
    CHECK(p.get_bool("on", false, d));
    CHECK_FALSE(p.get_bool("off", true, d));
    CHECK(p.get_spectrum("reflectance", d)->kind == SpectrumValue::Kind::Texture);
    CHECK(p.get_spectrum("L", d)->kind == SpectrumValue::Kind::Blackbody);
    CHECK(p.get_floats("uv", d).size() == 4);
    CHECK(p.get_float("missing", 7.0, d) == 7.0);
}

TEST_CASE("pbrt parameters: malformed lists are errors with the line", "[pbrt]") {
    CHECK_THAT(error_of([] { params_of("\"float\" 1"); }), Catch::Contains("must be \"type name\""));
    CHECK_THAT(error_of([] { params_of("\"floats radius\" 1"); }), Catch::Contains("unknown parameter type \"floats\""));
    CHECK_THAT(error_of([] { params_of("\"float radius\" \"two\""); }), Catch::Contains("takes finite numbers"));
    CHECK_THAT(error_of([] { params_of("\"integer n\" 1.5"); }), Catch::Contains("takes integers"));
    CHECK_THAT(error_of([] { params_of("\"point3 P\" [ 1 2 ]"); }), Catch::Contains("multiple of 3"));
    CHECK_THAT(error_of([] { params_of("\"rgb Kd\" [ 1 2 3 4 5 6 ]"); }), Catch::Contains("takes 3 numbers"));
    CHECK_THAT(error_of([] { params_of("\"bool b\" 1"); }), Catch::Contains("must be true or false"));
    CHECK_THAT(error_of([] { params_of("\"float r\" [ 1 2"); }), Catch::Contains("not closed"));
    CHECK_THAT(error_of([] { params_of("\"float r\" 1e999"); }), Catch::Contains("takes finite numbers"));
    CHECK_THAT(error_of([] { params_of("\"string s\" 3"); }), Catch::Contains("takes quoted strings"));
    // A parameter read with the wrong type.
    const Diagnostics d(false);
    const ParamList p = params_of("\"rgb radius\" [1 1 1]");
    CHECK_THAT(error_of([&] { p.get_float("radius", 1.0, d); }), Catch::Contains("has the wrong type: write \"float radius\""));
}

TEST_CASE("pbrt directives: malformed statements name file:line and say the fix", "[pbrt]") {
    const TempDir dir;
    CHECK_THAT(error_of([&] { convert_text(dir, "WorldBegin\nFrobnicate 1\n"); }),
               Catch::Contains("scene.pbrt:2: unknown directive \"Frobnicate\""));
    CHECK_THAT(error_of([&] { convert_text(dir, "Translate 1 2\nWorldBegin\n"); }), Catch::Contains("scene.pbrt:1: Translate takes 3 numbers"));
    CHECK_THAT(error_of([&] { convert_text(dir, "WorldBegin\nAttributeEnd\n"); }), Catch::Contains("AttributeEnd without a matching AttributeBegin"));
    CHECK_THAT(error_of([&] { convert_text(dir, "Shape \"sphere\"\n"); }), Catch::Contains("scene.pbrt:1: Shape must come after WorldBegin"));
    CHECK_THAT(error_of([&] { convert_text(dir, "WorldBegin\nCamera \"perspective\"\n"); }), Catch::Contains("must come before WorldBegin"));
    CHECK_THAT(error_of([&] { convert_text(dir, "LookAt 0 0 0 0 0 1 0 0 1\nWorldBegin\n"); }), Catch::Contains("LookAt: the eye"));
    CHECK_THAT(error_of([&] { convert_text(dir, world_with("NamedMaterial \"nope\"\nShape \"sphere\"")); }),
               Catch::Contains("scene.pbrt:5: NamedMaterial \"nope\": no material"));
    CHECK_THAT(error_of([&] { convert_text(dir, world_with("ObjectInstance \"nope\"")); }), Catch::Contains("no object of that name"));
    CHECK_THAT(error_of([&] { convert_text(dir, world_with("ObjectBegin \"a\"\nShape \"sphere\"")); }), Catch::Contains("never closed"));
    CHECK_THAT(error_of([&] { convert_text(dir, world_with("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 3]")); }),
               Catch::Contains("index 3 out of range"));
    CHECK_THAT(error_of([&] { convert_text(dir, world_with("Shape \"plymesh\" \"string filename\" \"none.ply\"")); }),
               Catch::Contains("\"none.ply\" not found"));
    CHECK_THAT(error_of([&] { convert_text(dir, world_with("Shape \"sphere\" \"float radius\" -1")); }), Catch::Contains("\"radius\" must be > 0"));
}

TEST_CASE("pbrt Include: relative to the main file's folder, nested, and bounded", "[pbrt]") {
    const TempDir dir;
    dir.write("parts/shapes.pbrt", "Include \"parts/more.pbrt\"\nShape \"sphere\" \"float radius\" 2\n");
    dir.write("parts/more.pbrt", "Shape \"sphere\" \"float radius\" 3\n");
    const auto c = convert_text(dir, world_with("Include \"parts/shapes.pbrt\"\nImport \"parts/more.pbrt\""));
    REQUIRE(c.doc["objects"].size() == 3);
    CHECK(c.doc["objects"][0]["radius"] == 3.0);
    CHECK(c.doc["objects"][1]["radius"] == 2.0);
    CHECK(c.doc["objects"][2]["radius"] == 3.0);
    dir.write("loop.pbrt", "Include \"loop.pbrt\"\n");
    CHECK_THAT(error_of([&] { convert_text(dir, "Include \"loop.pbrt\"\n"); }), Catch::Contains("nested deeper than 16"));
    CHECK_THAT(error_of([&] { convert_text(dir, "Include \"missing.pbrt\"\n"); }),
               Catch::Contains("scene.pbrt:1: Include: ") && Catch::Contains("no such file"));
}

TEST_CASE("pbrt spectra: blackbody at luminance 1, D65's temperature near white, named metals and glasses", "[pbrt]") {
    for (double t : {1800.0, 3000.0, 6504.0, 12000.0}) {
        const glm::dvec3 c = blackbody_rgb(t);
        INFO("T = " << t);
        CHECK(0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b == Approx(1.0).epsilon(0.02));  // Y of linear sRGB
    }
    const glm::dvec3 d65 = blackbody_rgb(6504.0);
    CHECK(std::fabs(d65.r - d65.b) < 0.12);  // D65's correlated colour temperature: nearly white
    const glm::dvec3 warm = blackbody_rgb(2000.0);
    CHECK(warm.r > warm.g);
    CHECK(warm.g > warm.b);
    std::string part;
    CHECK(named_metal("metal-CuZn-k", part) == std::optional<std::string>("CuZn"));
    CHECK(part == "k");
    CHECK_FALSE(named_metal("metal-Fe-eta", part));
    CHECK(*named_glass_ior("glass-BK7") == Approx(1.5168));
    CHECK_FALSE(named_glass_ior("glass-unknown"));
    CHECK(sampled_rgb({400, 0.0, 700, 1.0}).g == Approx(0.5));  // 550 nm, halfway
}

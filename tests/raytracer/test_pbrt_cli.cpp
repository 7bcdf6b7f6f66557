// `sweeptrace render scene.pbrt` and `sweeptrace convert` as a user runs them: the converted JSON,
// written to another folder, renders bit-identical to the .pbrt itself; bad input exits 2 with
// one line naming file:line and writes nothing; --strict refuses what would be approximated.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include "cli_run.hpp"
#include "raytracer/image/image.hpp"
#include "scene_test_files.hpp"

namespace fs = std::filesystem;
using sweeptrace::test::TempDir;

namespace {

using Run = sweeptrace::test::CliRun;

Run run(const fs::path& dir, const std::string& args) { return sweeptrace::test::run_sweeptrace(dir, args); }

std::string bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A small scene with a texture and a PLY mesh in subfolders (relative paths after conversion),
// conductors named and by rgb eta/k. A plain LookAt, as pbrt-v4's own scenes have: our camera
// is written left-handed, the PLY mesh stays as it is.
const char* kScene = R"(LookAt 0 1 -4  0 0.5 0  0 1 0
Camera "perspective" "float fov" 45
Film "rgb" "integer xresolution" 24 "integer yresolution" 16
Sampler "independent" "integer pixelsamples" 2
Integrator "path" "integer maxdepth" 3
WorldBegin
LightSource "infinite" "rgb L" [0.3 0.3 0.35]
LightSource "distant" "point3 from" [1 4 -2] "point3 to" [0 0 0] "rgb L" [2 2 2]
Texture "tex" "spectrum" "imagemap" "string filename" "textures/t.png"
MakeNamedMaterial "floor" "string type" "diffuse" "texture reflectance" "tex"
MakeNamedMaterial "glass" "string type" "dielectric" "float eta" 1.5
AttributeBegin
  NamedMaterial "floor"
  Shape "bilinearmesh" "point3 P" [ -3 0 -3  3 0 -3  -3 0 3  3 0 3 ]
AttributeEnd
AttributeBegin
  NamedMaterial "glass"
  Translate 0 0.5 0
  Shape "sphere" "float radius" 0.5
AttributeEnd
MakeNamedMaterial "gold" "string type" "conductor" "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k" "float roughness" 0.05
MakeNamedMaterial "copper" "string type" "conductor" "rgb eta" [0.2 0.9 1.1] "rgb k" [3.9 2.4 2.2]
AttributeBegin
  NamedMaterial "gold"
  Translate -1.2 0 0.3
  Scale 0.5 0.5 0.5
  Shape "plymesh" "string filename" "meshes/tet.ply"
AttributeEnd
AttributeBegin
  NamedMaterial "copper"
  Translate -0.6 0.3 -1
  Shape "sphere" "float radius" 0.3
AttributeEnd
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [3 3 3]
  Translate 1.2 0.4 0.5
  Shape "disk" "float radius" 0.3
AttributeEnd
)";

void write_scene(const TempDir& dir) {
    dir.write("in/scene.pbrt", kScene);
    sweeptrace::Image tex(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) tex.at(x, y) = glm::vec3((x + y) % 2 ? 0.8f : 0.2f, 0.5f, 0.3f);
    fs::create_directories(dir.path() / "in/textures");
    sweeptrace::write_image(tex, dir.path() / "in/textures/t.png");
    fs::create_directories(dir.path() / "out/deeper");
    dir.write("in/meshes/tet.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                   "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                                   "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
}

}  // namespace

TEST_CASE("pbrt CLI: convert writes JSON that renders bit-identical to the .pbrt, paths relative to the output", "[pbrt][cli]") {
    const TempDir dir;
    write_scene(dir);
    const Run c = run(dir.path(), "convert in/scene.pbrt -o out/deeper/scene.json --quiet");
    INFO(c.err);
    REQUIRE(c.exit_code == 0);
    CHECK(c.err.empty());  // every feature of this scene is supported
    const std::string json = bytes(dir.path() / "out/deeper/scene.json");
    CHECK(json.find("\"../../in/textures/t.png\"") != std::string::npos);
    CHECK(json.find("\"../../in/meshes/tet.ply\"") != std::string::npos);
    CHECK(json.find("\"metal\": \"Au\"") != std::string::npos);
    REQUIRE(run(dir.path(), "render in/scene.pbrt -o a.pfm --quiet --threads 2").exit_code == 0);
    REQUIRE(run(dir.path(), "render out/deeper/scene.json -o b.pfm --quiet --threads 1").exit_code == 0);
    const std::string a = bytes(dir.path() / "a.pfm"), b = bytes(dir.path() / "b.pfm");
    REQUIRE(a.size() > 24 * 16 * 12);
    CHECK(a == b);
    // Not all black: the scene was understood.
    const sweeptrace::Image img = sweeptrace::read_image(dir.path() / "a.pfm");
    double sum = 0.0;
    for (const auto& p : img.pixels) sum += p.r + p.g + p.b;
    CHECK(sum > 10.0);
}

TEST_CASE("pbrt CLI: the example Cornell box renders and converts without a warning", "[pbrt][cli]") {
    const TempDir dir;
    const fs::path scene = fs::path(SWEEPTRACE_SOURCE_DIR) / "scenes/pbrt/cornell-box.pbrt";
    const Run r = run(dir.path(), "render '" + scene.string() + "' --strict --quiet --spp 1 --width 20 --height 20");
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(fs::exists(dir.path() / "cornell-box.png"));  // the Film's filename is the default output
}

TEST_CASE("pbrt CLI: malformed scenes exit 2 with one line naming file:line, and nothing is written", "[pbrt][cli]") {
    const TempDir dir;
    dir.write("bad.pbrt", "WorldBegin\nShape \"sphere\" \"float radius\" [ 1\n");
    for (const char* args : {"convert bad.pbrt -o bad.json", "render bad.pbrt -o bad.png --quiet"}) {
        const Run r = run(dir.path(), args);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.err, Catch::StartsWith("sweeptrace: error: bad.pbrt:2: the values of \"float radius\" are not closed: add ']'"));
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
    CHECK_FALSE(fs::exists(dir.path() / "bad.json"));
    CHECK_FALSE(fs::exists(dir.path() / "bad.png"));
}

TEST_CASE("pbrt CLI: --strict refuses what the plain run warns about", "[pbrt][cli]") {
    const TempDir dir;
    dir.write("s.pbrt", "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\nShape \"curve\"\nShape \"sphere\"\n");
    const Run plain = run(dir.path(), "convert s.pbrt -o s.json --quiet");
    CHECK(plain.exit_code == 0);
    CHECK_THAT(plain.err, Catch::StartsWith("sweeptrace: warning: s.pbrt:3: Shape \"curve\" is not supported (ignored)"));
    fs::remove(dir.path() / "s.json");
    const Run strict = run(dir.path(), "convert s.pbrt -o s.json --strict");
    CHECK(strict.exit_code == 2);
    CHECK_THAT(strict.err, Catch::Contains("s.pbrt:3: Shape \"curve\" is not supported (ignored) (--strict makes this an error)"));
    CHECK_FALSE(fs::exists(dir.path() / "s.json"));
    CHECK(run(dir.path(), "render s.pbrt -o s.png --strict --quiet").exit_code == 2);
    CHECK_FALSE(fs::exists(dir.path() / "s.png"));
}

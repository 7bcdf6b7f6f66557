// `render --aovs` as a user runs it: the EXR holds the contract's channels (named as pbrt-v4's
// gbuffer film names them) and, bit for bit, the colour of a plain render with the sampler --aovs
// defaults to (sobol-halves; --sampler sobol, said, is kept); farm parts with features
// merge into the same file byte for byte (uniform and adaptive, split at odd sample indices);
// PNG and PFM outputs get their side files; the refusals exit 2 with one line and write nothing.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "cli_run.hpp"
#include "raytracer/image/feature_exr.hpp"
#include "raytracer/image/image.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;

namespace {

std::string aov_file_bytes(const std::filesystem::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// 20 x 14: a textured diffuse sphere, a glass one and a mirror floor under a sky.
std::filesystem::path write_aov_scene(const test::TempDir& dir, const std::string& film_extra = "") {
    return dir.write("aovs.json", R"({
  "camera": { "position": [0, 0.6, 5], "look_at": [0, 0, 0], "fov": 40 },
  "film": { "width": 20, "height": 14, "spp": 8, "max_depth": 5)" + film_extra + R"( },
  "background": { "sky": { "horizon": [1, 1, 1], "zenith": [0.3, 0.5, 1] } },
  "materials": { "m": { "type": "diffuse", "albedo": { "checker": { "a": [0.1, 0.2, 0.3], "b": [0.9, 0.8, 0.7], "scale": 4 } } },
                 "g": { "type": "dielectric", "ior": 1.5 },
                 "f": { "type": "metal", "albedo": [0.9, 0.9, 0.9], "roughness": 0 } },
  "objects": [ { "type": "sphere", "center": [-0.8, 0, 0], "radius": 0.7, "material": "m" },
               { "type": "sphere", "center": [0.8, 0, 0], "radius": 0.7, "material": "g" },
               { "type": "quad", "corner": [-3, -0.7, 3], "edge_u": [6, 0, 0], "edge_v": [0, 0, -6], "material": "f" } ]
})");
}

}  // namespace

TEST_CASE("aovs cli: the EXR holds the contract's channels and the plain render's colour", "[cli][aovs]") {
    test::TempDir dir;
    write_aov_scene(dir);
    REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs -o f.exr").exit_code == 0);
    REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --sampler sobol-halves -o plain.exr --variance var.exr")
                .exit_code == 0);
    const ExrChannels f = read_exr_channels(dir.path() / "f.exr");
    CHECK(f.width == 20);
    CHECK(f.height == 14);
    CHECK(f.spp == 8);
    // The contract, written out here rather than taken from the writer's list.
    std::vector<std::string> expected = {"R", "G", "B", "Variance.R", "Variance.G", "Variance.B", "Albedo.R", "Albedo.G", "Albedo.B",
                                         "Ns.X", "Ns.Y", "Ns.Z", "P.X", "P.Y", "P.Z", "AlbedoVariance.R", "AlbedoVariance.G",
                                         "AlbedoVariance.B", "NsVariance.X", "NsVariance.Y", "NsVariance.Z", "PVariance.Z"};
    for (const std::string half : {"Even.", "Odd."})
        for (const std::string c : {"R", "G", "B", "Albedo.R", "Albedo.G", "Albedo.B", "Ns.X", "Ns.Y", "Ns.Z", "P.X", "P.Y", "P.Z"})
            expected.push_back(half + c);
    for (const std::string& name : expected) {
        INFO(name);
        CHECK(f.channels.count(name) == 1);
    }
    CHECK(f.channels.size() == expected.size());
    // R, G, B: exactly what -o plain.exr (the same sampler) writes; Variance: what --variance writes, up to the
    // rounding of its double sum of squares (the feature file's are exact integer sums).
    const Image plain = read_image(dir.path() / "plain.exr");
    const Image var = read_image(dir.path() / "var.exr");
    const char* rgb[3] = {"R", "G", "B"};
    for (std::size_t i = 0; i < plain.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            CHECK(f.channels.at(rgb[c])[i] == plain.pixels[i][c]);
            CHECK(f.channels.at(std::string("Variance.") + rgb[c])[i] == Approx(var.pixels[i][c]).epsilon(1e-6).margin(1e-12));
        }
    // The sky (top rows) is a miss: zero features. The checker sphere is seen directly.
    CHECK(f.channels.at("P.Z")[0] == 0.0f);
    CHECK(f.channels.at("Albedo.R")[0] == 0.0f);
    const std::size_t centre_of_diffuse = 7 * 20 + 6;
    CHECK(f.channels.at("P.Z")[centre_of_diffuse] > 3.0f);
    CHECK(f.channels.at("Ns.Z")[centre_of_diffuse] > 0.5f);
}

TEST_CASE("aovs cli: --aovs renders with sobol-halves unless --sampler sobol is said", "[cli][aovs][sampler]") {
    test::TempDir dir;
    write_aov_scene(dir);
    REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs -o halves.exr").exit_code == 0);
    REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs --sampler sobol -o split.exr").exit_code == 0);
    REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet -o sobol.exr").exit_code == 0);
    const ExrChannels halves = read_exr_channels(dir.path() / "halves.exr"), split = read_exr_channels(dir.path() / "split.exr");
    const Image sobol = read_image(dir.path() / "sobol.exr");
    bool differs = false;
    for (std::size_t i = 0; i < sobol.pixels.size(); ++i) {
        CHECK(split.channels.at("R")[i] == sobol.pixels[i].x);
        differs = differs || halves.channels.at("R")[i] != sobol.pixels[i].x;
    }
    CHECK(differs);  // other numbers: the default under --aovs is not the plain render's sampler
}

TEST_CASE("aovs cli: farm parts with features merge into the whole render's EXR byte for byte", "[cli][aovs][farm]") {
    test::TempDir dir;
    write_aov_scene(dir);
    SECTION("uniform, split at an odd sample index") {
        REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs --spp 7 -o whole.exr").exit_code == 0);
        REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs --spp 7 --samples 0:3 -o a.exr").exit_code == 0);
        REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs --spp 7 --samples 3:7 -o b.exr").exit_code == 0);
        REQUIRE(test::run_sweeptrace(dir.path(), "merge b.exr a.exr -o merged.exr --quiet").exit_code == 0);
        CHECK(aov_file_bytes(dir.path() / "merged.exr") == aov_file_bytes(dir.path() / "whole.exr"));
        // A part without features is another render: refused by name, nothing written.
        REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --spp 7 --samples 3:7 -o plain.exr").exit_code == 0);
        const test::CliRun bad = test::run_sweeptrace(dir.path(), "merge a.exr plain.exr -o mixed.exr");
        CHECK(bad.exit_code == 2);
        CHECK_THAT(bad.err, Catch::Contains("feature outputs (--aovs) 'on' vs 'off'"));
        CHECK_FALSE(std::filesystem::exists(dir.path() / "mixed.exr"));
    }
    SECTION("adaptive, parts inside and past the pilot") {
        const std::string common = "render aovs.json --quiet --aovs --adaptive on --spp 24 ";
        REQUIRE(test::run_sweeptrace(dir.path(), common + "-o whole.exr").exit_code == 0);
        REQUIRE(test::run_sweeptrace(dir.path(), common + "--samples 0:5 -o a.exr").exit_code == 0);
        REQUIRE(test::run_sweeptrace(dir.path(), common + "--samples 5:19 -o b.exr").exit_code == 0);
        REQUIRE(test::run_sweeptrace(dir.path(), common + "--samples 19:24 -o c.exr").exit_code == 0);
        REQUIRE(test::run_sweeptrace(dir.path(), "merge a.exr b.exr c.exr -o merged.exr --quiet").exit_code == 0);
        CHECK(aov_file_bytes(dir.path() / "merged.exr") == aov_file_bytes(dir.path() / "whole.exr"));
    }
    SECTION("the scene key film.aovs asks for the same") {
        write_aov_scene(dir, R"(, "aovs": true)");
        REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet -o key.exr").exit_code == 0);
        REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs -o flag.exr").exit_code == 0);
        CHECK(aov_file_bytes(dir.path() / "key.exr") == aov_file_bytes(dir.path() / "flag.exr"));
        CHECK(read_exr_channels(dir.path() / "key.exr").channels.count("Albedo.R") == 1);
    }
}

TEST_CASE("aovs cli: PNG and PFM outputs get albedo, normal and depth PFMs beside them", "[cli][aovs]") {
    test::TempDir dir;
    write_aov_scene(dir);
    REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs -o out.png").exit_code == 0);
    REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs -o f.exr").exit_code == 0);
    const ExrChannels f = read_exr_channels(dir.path() / "f.exr");
    const Image albedo = read_image(dir.path() / "out.albedo.pfm");
    const Image normal = read_image(dir.path() / "out.normal.pfm");
    const Image depth = read_image(dir.path() / "out.depth.pfm");
    REQUIRE(albedo.width == 20);
    for (int y = 0; y < 14; ++y)
        for (int x = 0; x < 20; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * 20 + x;
            CHECK(albedo.at(x, y).y == f.channels.at("Albedo.G")[i]);
            CHECK(normal.at(x, y).z == f.channels.at("Ns.Z")[i]);
            CHECK(depth.at(x, y).x == f.channels.at("P.Z")[i]);
        }
    REQUIRE(test::run_sweeptrace(dir.path(), "render aovs.json --quiet --aovs -o out.pfm").exit_code == 0);
    CHECK(std::filesystem::exists(dir.path() / "out.depth.pfm"));
}

TEST_CASE("aovs cli: a side file that is another output or an input is refused before rendering", "[cli][aovs][bad-input]") {
    test::TempDir dir;
    write_aov_scene(dir);
    const test::CliRun clash = test::run_sweeptrace(dir.path(), "render aovs.json --aovs -o out.png --variance out.albedo.pfm");
    CHECK(clash.exit_code == 2);
    CHECK_THAT(clash.err, Catch::StartsWith("sweeptrace: error: --aovs side file 'out.albedo.pfm' is the same file as --variance"));
    CHECK_FALSE(std::filesystem::exists(dir.path() / "out.png"));
    CHECK_FALSE(std::filesystem::exists(dir.path() / "out.albedo.pfm"));
    // The scene itself named as a side file: `-o aovs.png` writes aovs.albedo.pfm etc.; a scene
    // called aovs.depth.pfm would be overwritten.
    std::filesystem::copy_file(dir.path() / "aovs.json", dir.path() / "s.depth.pfm");
    const test::CliRun over = test::run_sweeptrace(dir.path(), "render s.depth.pfm --aovs -o s.png");
    CHECK(over.exit_code == 2);
    CHECK_THAT(over.err, Catch::Contains("--aovs side file 's.depth.pfm' is the scene"));
    CHECK_FALSE(std::filesystem::exists(dir.path() / "s.png"));
    CHECK(aov_file_bytes(dir.path() / "s.depth.pfm") == aov_file_bytes(dir.path() / "aovs.json"));
    // A scene key of the wrong type names the key.
    write_aov_scene(dir, R"(, "aovs": "yes")");
    const test::CliRun key = test::run_sweeptrace(dir.path(), "render aovs.json -o k.exr");
    CHECK(key.exit_code == 2);
    CHECK_THAT(key.err, Catch::Contains("film.aovs"));
    CHECK_FALSE(std::filesystem::exists(dir.path() / "k.exr"));
}

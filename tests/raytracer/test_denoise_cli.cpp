// `sweeptrace denoise` as a user runs it: a feature image in, the denoised image out, the input
// untouched; bad input refused with one line and nothing written.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli_run.hpp"
#include "denoise_test_images.hpp"
#include "image_test_support.hpp"
#include "raytracer/image/exr_channels.hpp"
#include "raytracer/image/image.hpp"

namespace {

using namespace sweeptrace;
using namespace sweeptrace::testing;

std::string bytes_of(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("denoise cli: writes the denoised image and leaves the feature image as it was", "[denoise][cli]") {
    ScratchDir dir("denoise-cli");
    const SyntheticImage s = textured_image(40, 24, 3, 0.1f);
    write_exr_channels(as_channels(s.input), dir / "in.exr");
    const std::string before = bytes_of(dir / "in.exr");
    const test::CliRun r = test::run_sweeptrace(dir.path(), "denoise in.exr -o out.exr --threads 2");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(bytes_of(dir / "in.exr") == before);
    const Image out = read_image(dir / "out.exr");
    CHECK(out.width == 40);
    CHECK(out.height == 24);
    // Denoised: closer to the truth than the raw mean is.
    double raw = 0.0, denoised = 0.0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 40; ++x)
            for (int c = 0; c < 3; ++c) {
                const double t = s.truth.at(c, x, y);
                raw += (s.input.color.mean.at(c, x, y) - t) * (s.input.color.mean.at(c, x, y) - t);
                denoised += (out.at(x, y)[c] - t) * (out.at(x, y)[c] - t);
            }
    CHECK(denoised < 0.25 * raw);
}

TEST_CASE("denoise cli: an image without features, a NaN feature, -o naming the input: exit 2, one line, nothing written",
          "[denoise][cli]") {
    ScratchDir dir("denoise-cli-bad");
    const SyntheticImage s = textured_image(16, 8, 3, 0.1f);
    ExrChannels good = as_channels(s.input);
    write_exr_channels(good, dir / "in.exr");
    write_image(Image(16, 8), dir / "plain.exr");
    ExrChannels nan = good;
    nan.channels["Even.P.Z"][3] = std::nanf("");
    write_exr_channels(nan, dir / "nan.exr");

    test::CliRun r = test::run_sweeptrace(dir.path(), "denoise plain.exr -o out.exr");
    CHECK(r.exit_code == 2);
    CHECK(r.err == "sweeptrace: error: 'plain.exr' has no channel 'Even.R': denoise needs colour, features (Albedo, Ns, P.Z), their "
                   "variances and Even./Odd. halves, as render --aovs writes them\n");
    r = test::run_sweeptrace(dir.path(), "denoise nan.exr -o out.exr");
    CHECK(r.exit_code == 2);
    CHECK(r.err == "sweeptrace: error: 'nan.exr': channel 'Even.P.Z' is NaN at pixel (3, 0)\n");
    const std::string before = bytes_of(dir / "in.exr");
    r = test::run_sweeptrace(dir.path(), "denoise in.exr -o ./in.exr");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("output './in.exr' is the image to denoise 'in.exr'") != std::string::npos);
    CHECK(bytes_of(dir / "in.exr") == before);
    CHECK_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST_CASE("render --denoise: the feature image -o names is kept and the denoised image written beside it", "[denoise][cli]") {
    ScratchDir dir("render-denoise");
    const std::string scene = std::string(SWEEPTRACE_SOURCE_DIR) + "/scenes/cornell-box.json";
    test::CliRun r = test::run_sweeptrace(dir.path(), "render '" + scene + "' --width 24 --height 24 --spp 4 --threads 2 -o raw.exr --denoise clean.pfm --quiet");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const ExrChannels raw = read_exr_channels(dir / "raw.exr");
    CHECK(raw.find("Even.Albedo.R") != nullptr);
    const Image clean = read_image(dir / "clean.pfm");
    CHECK(clean.width == 24);
    // the same as denoising the kept feature image afterwards
    r = test::run_sweeptrace(dir.path(), "denoise raw.exr -o again.pfm --threads 1 --quiet");
    REQUIRE(r.exit_code == 0);
    CHECK(bytes_of(dir / "again.pfm") == bytes_of(dir / "clean.pfm"));

    r = test::run_sweeptrace(dir.path(), "render '" + scene + "' --width 24 --height 24 --spp 4 -o raw.png --denoise clean2.pfm --quiet");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--denoise needs -o OUT.exr") != std::string::npos);
    r = test::run_sweeptrace(dir.path(), "render '" + scene + "' --width 24 --height 24 --spp 4 -o raw2.exr --denoise ./raw2.exr --quiet");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--denoise './raw2.exr' is the same file as output 'raw2.exr'") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "clean2.pfm"));
    CHECK_FALSE(std::filesystem::exists(dir / "raw2.exr"));
}

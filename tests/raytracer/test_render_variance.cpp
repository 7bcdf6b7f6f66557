// `render --variance` and the noise test of `diff` on real renders (issue #14 part 3).
#include <catch2/catch.hpp>

#include "image_test_support.hpp"
#include "raytracer/image/image.hpp"

using namespace sweeptrace;
using sweeptrace::testing::run_sweeptrace;
using sweeptrace::testing::ScratchDir;
using Catch::Matchers::Contains;

namespace {

const std::string cornell = std::string(SWEEPTRACE_SOURCE_DIR) + "/scenes/cornell-box.json";

// Independent samples: the samples' variance / spp is then exactly what the pixel mean's variance
// is estimated by. (Under the default Sobol sampler the same formula overstates it, see below.)
void render_seed(const ScratchDir& dir, int seed, const std::string& stem, const std::string& sampler = "independent") {
    const auto r = run_sweeptrace("render " + cornell + " --sampler " + sampler +
                                      " --width 32 --height 32 --spp 16 --quiet --threads 1 --seed " +
                                      std::to_string(seed) + " -o " + (dir / (stem + ".exr")).string() + " --variance " +
                                      (dir / (stem + "-var.exr")).string(),
                                  dir.path());
    REQUIRE(r.exit_code == 0);
}

}  // namespace

TEST_CASE("render --variance: the variance of the pixel mean, consistent with two seeds", "[render][cli][variance]") {
    ScratchDir dir("render-variance");
    render_seed(dir, 1, "a");
    render_seed(dir, 2, "b");
    const Image a = read_image(dir / "a.exr"), b = read_image(dir / "b.exr");
    const Image va = read_image(dir / "a-var.exr"), vb = read_image(dir / "b-var.exr");
    REQUIRE(va.width == 32);
    // E[(a - b)^2] = Var(a) + Var(b) per pixel: summed over the image the ratio is near 1 if the
    // files hold the variance of the mean (a variance of the samples would be 16 times larger).
    double squares = 0.0, variances = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            REQUIRE(va.pixels[i][c] >= 0.0f);
            const double d = a.pixels[i][c] - b.pixels[i][c];
            squares += d * d;
            variances += va.pixels[i][c] + vb.pixels[i][c];
        }
    CHECK(squares / variances > 0.6);
    CHECK(squares / variances < 1.6);

    SECTION("diff with both variances passes the noise-only pair and rejects +10 % exposure") {
        const std::string vars = " --variance-a " + (dir / "a-var.exr").string() + " --variance-b " + (dir / "b-var.exr").string();
        const auto same = run_sweeptrace("diff " + (dir / "a.exr").string() + " " + (dir / "b.exr").string() + vars, dir.path());
        CHECK(same.exit_code == 0);
        CHECK_THAT(same.output, Contains("within tolerance"));
        Image bright = a;
        for (auto& p : bright.pixels) p *= 1.1f;
        write_image(bright, dir / "bright.exr");
        CHECK(run_sweeptrace("diff " + (dir / "bright.exr").string() + " " + (dir / "b.exr").string() + vars, dir.path())
                  .exit_code == 1);
    }
}

TEST_CASE("render --variance under Sobol: the stated variance does not understate the error", "[render][cli][variance]") {
    // Stratified samples make the pixel mean's error smaller than the iid formula says; the file
    // is then an overstatement, which keeps diff's noise test conservative (fewer false alarms,
    // less power), never one that would make a noise-only pair fail.
    ScratchDir dir("render-variance-sobol");
    render_seed(dir, 1, "a", "sobol");
    render_seed(dir, 2, "b", "sobol");
    const Image a = read_image(dir / "a.exr"), b = read_image(dir / "b.exr");
    const Image va = read_image(dir / "a-var.exr"), vb = read_image(dir / "b-var.exr");
    double squares = 0.0, variances = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = a.pixels[i][c] - b.pixels[i][c];
            squares += d * d;
            variances += va.pixels[i][c] + vb.pixels[i][c];
        }
    INFO("squared differences / stated variance: " << squares / variances);
    CHECK(squares / variances < 1.0);
}

TEST_CASE("render --variance refuses an 8-bit file before rendering", "[render][cli][variance]") {
    ScratchDir dir("render-variance-bad");
    const auto r = run_sweeptrace("render " + cornell + " --width 8 --height 8 --spp 2 --quiet -o " +
                                      (dir / "a.exr").string() + " --variance " + (dir / "v.png").string(),
                                  dir.path());
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("v.png"));
    CHECK_FALSE(std::filesystem::exists(dir / "a.exr"));
}

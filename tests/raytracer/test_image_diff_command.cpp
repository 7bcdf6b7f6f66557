#include <catch2/catch.hpp>

#include "image_test_support.hpp"
#include "raytracer/image/image.hpp"

using namespace sweeptrace;
using sweeptrace::testing::run_sweeptrace;
using sweeptrace::testing::ScratchDir;
using Catch::Matchers::Contains;

namespace {

Image gradient(int w, int h, float offset) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.at(x, y) = glm::vec3(float(x) / w, float(y) / h, 0.5f) + offset;
    return image;
}

}  // namespace

TEST_CASE("sweeptrace diff: exit 0 within tolerance, 1 over it, heatmap written", "[image][diff][cli]") {
    ScratchDir dir("diff-cli");
    const std::string a = (dir / "a.png").string(), b = (dir / "b.pfm").string(), c = (dir / "c.exr").string();
    write_image(gradient(32, 16, 0.0f), a);
    write_image(gradient(32, 16, 0.0f), b);
    write_image(gradient(32, 16, 0.2f), c);

    auto same = run_sweeptrace("diff " + a + " " + b, dir.path());
    CHECK(same.exit_code == 0);
    CHECK_THAT(same.output, Contains("RMSE") && Contains("PSNR") && Contains("within tolerance"));

    const std::string heat = (dir / "heat.png").string();
    auto over = run_sweeptrace("diff " + a + " " + c + " --heatmap " + heat, dir.path());
    CHECK(over.exit_code == 1);
    CHECK_THAT(over.output, Contains("OVER tolerance"));
    REQUIRE(std::filesystem::exists(heat));
    CHECK(read_image(heat).width == 32);

    // Loose enough thresholds accept the same pair.
    const std::string loose_flip = " --max-flip 1 --max-local-flip 1 --warn-flip 1";
    auto loose = run_sweeptrace("diff " + a + " " + c + " --max-rmse 1 --max-share 1" + loose_flip, dir.path());
    CHECK(loose.exit_code == 0);
    // A threshold on the perceptual metric alone can reject it.
    auto perceptual = run_sweeptrace("diff " + a + " " + c + " --max-rmse 1 --max-share 1 --max-delta-e 0.5" + loose_flip, dir.path());
    CHECK(perceptual.exit_code == 1);
}

TEST_CASE("sweeptrace diff: exit 2 with a clear message on bad input", "[image][diff][cli]") {
    ScratchDir dir("diff-cli-bad");
    const std::string a = (dir / "a.png").string(), small = (dir / "small.png").string();
    write_image(gradient(32, 16, 0.0f), a);
    write_image(gradient(16, 16, 0.0f), small);

    auto missing = run_sweeptrace("diff " + a + " " + (dir / "none.png").string(), dir.path());
    CHECK(missing.exit_code == 2);
    CHECK_THAT(missing.output, Contains("none.png"));

    auto size = run_sweeptrace("diff " + a + " " + small, dir.path());
    CHECK(size.exit_code == 2);
    CHECK_THAT(size.output, Contains("32x16") && Contains("16x16"));

    testing::write_file_text(dir / "junk.exr", "junk");
    auto junk = run_sweeptrace("diff " + a + " " + (dir / "junk.exr").string(), dir.path());
    CHECK(junk.exit_code == 2);
    CHECK_THAT(junk.output, Contains("junk.exr"));

    auto no_args = run_sweeptrace("diff " + a, dir.path());
    CHECK(no_args.exit_code == 2);

    // An unwritable heatmap path is bad input too, and nothing is left behind.
    auto bad_heat = run_sweeptrace("diff " + a + " " + a + " --heatmap " + (dir / "x" / "h.png").string(), dir.path());
    CHECK(bad_heat.exit_code == 2);
    CHECK_FALSE(std::filesystem::exists(dir / "x"));
}

TEST_CASE("sweeptrace diff --help documents the defaults", "[image][diff][cli]") {
    ScratchDir dir("diff-cli-help");
    auto help = run_sweeptrace("diff --help", dir.path());
    CHECK(help.exit_code == 0);
    CHECK_THAT(help.output, Contains("--max-rmse") && Contains("0.05") && Contains("--max-share") &&
                                Contains("0.01") && Contains("--pixel-threshold") && Contains("0.1"));
}

// Folder mode of `sweeptrace diff` (issue #14 part 4): matching by name, per-image verdicts, one
// exit code, JSON, JUnit XML, and the HTML report rendered by headless Chromium.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "image_test_support.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/srgb.hpp"

using namespace sweeptrace;
using sweeptrace::testing::read_file_text;
using sweeptrace::testing::run_sweeptrace;
using sweeptrace::testing::ScratchDir;
using Catch::Matchers::Contains;

namespace {

Image flat(int w, int h, glm::vec3 v) {
    Image image(w, h);
    for (auto& p : image.pixels) p = v;
    return image;
}

Image pattern(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.at(x, y) = glm::vec3(float(x) / w, float(y) / h, 0.4f);
    return image;
}

struct Folders {
    ScratchDir dir{"diff-folder"};
    std::filesystem::path golden = dir / "golden", actual = dir / "actual";
    Folders() {
        std::filesystem::create_directories(golden);
        std::filesystem::create_directories(actual);
    }
    std::string args() const { return "diff --golden " + golden.string() + " --actual " + actual.string(); }
};

}  // namespace

TEST_CASE("diff folder mode: one verdict per name, one exit code, JSON and JUnit", "[image][diff][cli][folder]") {
    Folders f;
    write_image(pattern(32, 24), f.golden / "same.png");
    write_image(pattern(32, 24), f.actual / "same.png");
    Image defect = pattern(32, 24);
    for (int y = 8; y < 12; ++y)
        for (int x = 8; x < 12; ++x) defect.at(x, y) = glm::vec3(1.0f);
    write_image(pattern(32, 24), f.golden / "square.png");
    write_image(defect, f.actual / "square.png");
    write_image(pattern(32, 24), f.actual / "extra.png");  // no golden: listed, not compared

    const std::string json = (f.dir / "r.json").string(), junit = (f.dir / "r.xml").string();
    const auto r = run_sweeptrace(f.args() + " --json " + json + " --junit " + junit, f.dir.path());
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.output, Contains("extra.png: no golden"));
    const nlohmann::json j = nlohmann::json::parse(read_file_text(json));
    REQUIRE(j["images"].size() == 2);
    CHECK(j["exit_code"] == 1);
    CHECK(j["images"][0]["name"] == "same.png");
    CHECK(j["images"][0]["status"] == "pass");
    CHECK(j["images"][0]["flip"]["mean"] == 0.0);
    CHECK(j["images"][1]["status"] == "FAIL");
    CHECK(j["images"][1]["failures"].size() >= 1);
    const std::string x = read_file_text(junit);
    CHECK_THAT(x, Contains("<testsuites") && Contains("tests=\"2\" failures=\"1\" errors=\"0\"") &&
                      Contains("<testcase classname=\"sweeptrace.diff\" name=\"square.png\"") && Contains("<failure message="));

    SECTION("a golden without an actual image is an error: exit 2, reported, others still judged") {
        write_image(pattern(32, 24), f.golden / "lost.png");
        const auto lost = run_sweeptrace(f.args() + " --junit " + junit, f.dir.path());
        CHECK(lost.exit_code == 2);
        CHECK_THAT(read_file_text(junit), Contains("errors=\"1\"") && Contains("<error message=\"no actual image"));
        CHECK_THAT(lost.output, Contains("square.png") && Contains("FAIL"));
    }
    SECTION("all matching: exit 0") {
        write_image(pattern(32, 24), f.actual / "square.png");
        CHECK(run_sweeptrace(f.args(), f.dir.path()).exit_code == 0);
    }
}

TEST_CASE("diff folder mode: NAME-variance.exr in both folders turns on the noise test", "[image][diff][cli][folder]") {
    Folders f;
    const Image truth = pattern(32, 32);
    Image a = truth, b = truth;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) a.pixels[i] += glm::vec3(i % 2 ? 0.02f : -0.02f);
    write_image(b, f.golden / "r.exr");
    write_image(a, f.actual / "r.exr");
    const Image v = flat(32, 32, glm::vec3(0.02f * 0.02f));
    write_image(v, f.golden / "r-variance.exr");
    write_image(v, f.actual / "r-variance.exr");
    const std::string json = (f.dir / "r.json").string();
    CHECK(run_sweeptrace(f.args() + " --json " + json, f.dir.path()).exit_code == 0);
    const nlohmann::json j = nlohmann::json::parse(read_file_text(json));
    REQUIRE(j["images"].size() == 1);  // the variance files are not images to compare
    CHECK(j["images"][0]["noise_test"]["blocks_tested"] == 16);
}

TEST_CASE("diff --html: headless Chromium shows golden, actual and heatmap panels", "[image][diff][cli][folder][html]") {
    INFO("chromium is needed for this test: run tools/install-deps.sh");
    REQUIRE(std::system("command -v chromium >/dev/null 2>&1") == 0);
    Folders f;
    // Three flat panels of distinct colours, so each can be found in the screenshot by its own
    // pixels: the golden's, the actual's, and the heatmap's (one FLIP value everywhere).
    write_image(flat(64, 48, glm::vec3(0.6f, 0.05f, 0.3f)), f.golden / "p.png");
    write_image(flat(64, 48, glm::vec3(0.05f, 0.3f, 0.25f)), f.actual / "p.png");
    const std::filesystem::path html = f.dir / "report";
    REQUIRE(run_sweeptrace(f.args() + " --html " + html.string(), f.dir.path()).exit_code == 1);
    REQUIRE(std::filesystem::exists(html / "index.html"));
    CHECK_THAT(read_file_text(html / "index.html"), Contains("p.png.html") && Contains("p.png.heatmap.png"));
    CHECK_THAT(read_file_text(html / "p.png.html"), Contains("cp ") && Contains("legend"));

    const std::filesystem::path profile = f.dir / "chromium-profile", shot = f.dir / "shot.png";
    const std::string command =
        "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
        "--disable-background-networking --disable-component-update --disable-sync --hide-scrollbars "
        "--user-data-dir=" + profile.string() + " --window-size=1400,1000 --screenshot=" + shot.string() +
        " file://" + (html / "p.png.html").string() + " >" + (f.dir / "chromium.log").string() + " 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    const Image screen = read_image(shot);
    REQUIRE(screen.width == 1400);

    auto code = [](const glm::vec3& linear) {
        return glm::ivec3(to_byte(srgb_encode(linear.r)), to_byte(srgb_encode(linear.g)), to_byte(srgb_encode(linear.b)));
    };
    double centre[3];
    int index = 0;
    for (const char* panel : {"golden", "actual", "heatmap"}) {
        const glm::ivec3 want = code(read_image(html / ("p.png." + std::string(panel) + ".png")).pixels[0]);
        std::size_t count = 0;
        double sum_x = 0.0;
        for (int y = 0; y < screen.height; ++y)
            for (int x = 0; x < screen.width; ++x) {
                const glm::ivec3 d = glm::abs(code(screen.at(x, y)) - want);
                if (d.x <= 2 && d.y <= 2 && d.z <= 2) {
                    ++count;
                    sum_x += x;
                }
            }
        INFO(panel << ": " << count << " pixels of its colour");
        // A third of 1400 px wide at the image's 4:3 is ~440 x 330 px; accept half of that.
        CHECK(count > 70000);
        centre[index++] = count ? sum_x / double(count) : 0.0;
    }
    CHECK(centre[0] < centre[1]);  // golden | actual | heatmap, left to right
    CHECK(centre[1] < centre[2]);
    CHECK(centre[2] < 1400.0);
}

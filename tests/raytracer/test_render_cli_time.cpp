// `sweeptrace render --time / --time-clock / --guiding` as a user runs them: a spent budget
// writes the finished passes and says how many; bad values exit 2 without touching the output.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_run.hpp"
#include "raytracer/image/image.hpp"

namespace fs = std::filesystem;

namespace {

using Run = sweeptrace::test::CliRun;

Run run(const fs::path& dir, const std::string& args) { return sweeptrace::test::run_sweeptrace(dir, args); }

fs::path scene_dir(const std::string& name) {
    const fs::path d = fs::path(SWEEPTRACE_BINARY_DIR) / "render-cli-time-tests" / name;
    fs::remove_all(d);
    fs::create_directories(d);
    std::ofstream(d / "ball.json") << R"({
  "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 40 },
  "film": { "width": 24, "height": 12, "spp": 4, "max_depth": 4, "guiding": true },
  "background": { "sky": { "horizon": [1, 1, 1], "zenith": [0.3, 0.5, 1] } },
  "materials": { "m": { "type": "diffuse", "albedo": [0.6, 0.5, 0.4] } },
  "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ]
})";
    return d;
}

}  // namespace

TEST_CASE("render cli: --time renders whole passes and reports the spp reached", "[render][cli][time]") {
    const fs::path dir = scene_dir("time");
    // A budget spent at once: the first pass is still rendered and written.
    const Run r = run(dir, "render ball.json -o a.pfm --time 1e-9 --time-clock cpu");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("spent: 1 spp reached") != std::string::npos);
    CHECK(r.err.find("1 spp guided") != std::string::npos);  // film.guiding: true
    CHECK(sweeptrace::read_image(dir / "a.pfm").width == 24);
    // A generous budget with --spp: the spp comes first; --guiding off overrides the scene.
    const Run s = run(dir, "render ball.json -o b.pfm --time 600 --spp 3 --guiding off");
    INFO(s.err);
    REQUIRE(s.exit_code == 0);
    CHECK(s.err.find(", 3 spp, ") != std::string::npos);
    CHECK(s.err.find("spent") == std::string::npos);
}

TEST_CASE("render cli: bad --time, --time-clock or --guiding exit 2 and write nothing", "[render][cli][time]") {
    const fs::path dir = scene_dir("bad-time");
    for (const std::string extra : {"--time 0", "--time -2", "--time nan", "--time-clock gpu", "--guiding yes"}) {
        const Run r = run(dir, "render ball.json -o out.png --quiet " + extra);
        INFO(extra << ": " << r.err);
        CHECK(r.exit_code == 2);
        CHECK_FALSE(r.err.empty());
        CHECK_FALSE(fs::exists(dir / "out.png"));
    }
}

// `sweeptrace render --sampler`: the two names are accepted (and change the image), any other
// exits 2 naming the option, and writes nothing.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "raytracer/image/image.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kBinary = fs::path(SWEEPTRACE_BINARY_DIR) / "sweeptrace";

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs the binary through the shell with stderr captured to a file; returns the exit status.
int run(const fs::path& dir, const std::string& args, std::string& err) {
    const std::string cmd = "cd '" + dir.string() + "' && '" + kBinary.string() + "' " + args + " 2> err.txt";
    const int status = std::system(cmd.c_str());
    err = slurp(dir / "err.txt");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("render cli: --sampler sobol|independent, anything else exits 2", "[render][cli][sampler]") {
    const fs::path dir = fs::temp_directory_path() / "sweeptrace-cli-sampler";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "ball.json")
        << R"({ "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0] }, "film": { "width": 8, "height": 8, "spp": 4 },
               "background": { "color": [1, 1, 1] }, "materials": { "m": { "type": "diffuse" } },
               "objects": [{ "type": "sphere", "radius": 1, "material": "m" }] })";
    std::string err;
    REQUIRE(run(dir, "render ball.json --quiet --sampler sobol -o s.pfm", err) == 0);
    REQUIRE(run(dir, "render ball.json --quiet --sampler independent -o i.pfm", err) == 0);
    REQUIRE(run(dir, "render ball.json --quiet -o d.pfm", err) == 0);
    const auto pixels = [&](const char* name) { return sweeptrace::read_image(dir / name).pixels; };
    CHECK(pixels("s.pfm") == pixels("d.pfm"));  // sobol is the default
    CHECK(pixels("s.pfm") != pixels("i.pfm"));
    CHECK(run(dir, "render ball.json --quiet --sampler halton -o h.pfm", err) == 2);
    CHECK(err.find("--sampler") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "h.pfm"));
    fs::remove_all(dir);
}

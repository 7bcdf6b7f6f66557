// `sweeptrace render` as a user runs it: option validation (exit 2, nothing written or
// overwritten), the default output name, --width/--height keeping the aspect ratio, and Ctrl-C
// writing the samples finished so far with exit 130.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "raytracer/image/image.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kBinary = fs::path(SWEEPTRACE_BINARY_DIR) / "sweeptrace";

struct Run {
    int exit_code = -1;
    std::string err;
};

// Starts the binary in `dir` with stderr on a pipe; `on_line` sees each stderr line as it comes
// and may act on the child (e.g. interrupt it).
template <class OnLine>
Run run_in(const fs::path& dir, const std::vector<std::string>& args, OnLine on_line) {
    int pipefd[2];
    REQUIRE(pipe(pipefd) == 0);
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        dup2(pipefd[1], STDERR_FILENO);
        const int devnull = open("/dev/null", O_WRONLY);
        dup2(devnull, STDOUT_FILENO);
        close(pipefd[0]);
        close(pipefd[1]);
        if (chdir(dir.c_str()) != 0) _exit(99);
        std::vector<char*> argv;
        std::string bin = kBinary.string();
        argv.push_back(bin.data());
        std::vector<std::string> copy = args;
        for (std::string& a : copy) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(bin.c_str(), argv.data());
        _exit(98);
    }
    close(pipefd[1]);
    Run r;
    std::string line;
    char c;
    while (read(pipefd[0], &c, 1) == 1) {
        r.err.push_back(c);
        if (c == '\n') {
            on_line(line, pid);
            line.clear();
        } else {
            line.push_back(c);
        }
    }
    close(pipefd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

Run run_in(const fs::path& dir, const std::vector<std::string>& args) {
    return run_in(dir, args, [](const std::string&, pid_t) {});
}

fs::path fresh_dir(const std::string& name) {
    const fs::path d = fs::path(SWEEPTRACE_BINARY_DIR) / "render-cli-tests" / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// A 40x20 scene: a diffuse sphere under a sky.
void write_scene(const fs::path& file, int spp = 2) {
    std::ofstream(file) << R"({
  "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 40 },
  "film": { "width": 40, "height": 20, "spp": )" << spp << R"(, "max_depth": 4 },
  "background": { "sky": { "horizon": [1, 1, 1], "zenith": [0.3, 0.5, 1] } },
  "materials": { "m": { "type": "diffuse", "albedo": [0.6, 0.5, 0.4] } },
  "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ]
})";
}

std::string slurp(const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("render cli: renders to the scene's name in the current directory, --width alone keeps the aspect", "[render][cli]") {
    const fs::path dir = fresh_dir("default-name");
    write_scene(dir / "ball.json");
    const Run r = run_in(dir, {"render", "ball.json", "--quiet"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());  // --quiet: nothing on stderr
    const sweeptrace::Image img = sweeptrace::read_image(dir / "ball.png");
    CHECK(img.width == 40);
    CHECK(img.height == 20);

    const Run w = run_in(dir, {"render", "ball.json", "--width", "10", "-o", "small.pfm", "--threads", "1"});
    INFO(w.err);
    REQUIRE(w.exit_code == 0);
    const sweeptrace::Image small = sweeptrace::read_image(dir / "small.pfm");
    CHECK(small.width == 10);
    CHECK(small.height == 5);
    // Not quiet and not a terminal: progress lines and a summary with the rates.
    CHECK(w.err.find("render: 100%") != std::string::npos);
    CHECK(w.err.find("samples/s") != std::string::npos);
    CHECK(w.err.find("rays/s") != std::string::npos);
}

TEST_CASE("render cli: bad options exit 2 with a message and leave existing output untouched", "[render][cli]") {
    const fs::path dir = fresh_dir("bad-options");
    write_scene(dir / "ball.json");
    std::ofstream(dir / "out.png") << "precious";
    const std::vector<std::vector<std::string>> bad = {
        {"--spp", "0"},         {"--width", "0"},       {"--height", "-3"}, {"--threads", "-1"},
        {"--max-depth", "0"},   {"--accel", "octree"},  {"--spp", "many"},  {"-o", "out.jpg"},
        {"-o", "nowhere/x.png"}};
    for (const auto& extra : bad) {
        std::vector<std::string> args = {"render", "ball.json", "--quiet"};
        if (extra[0] != "-o") args.insert(args.end(), {"-o", "out.png"});
        args.insert(args.end(), extra.begin(), extra.end());
        const Run r = run_in(dir, args);
        INFO(extra[0] << " " << extra[1] << ": " << r.err);
        CHECK(r.exit_code == 2);
        CHECK(r.err.find(extra[0] == "-o" ? "out" : extra[0].substr(2)) != std::string::npos);
    }
    const Run missing = run_in(dir, {"render", "absent.json", "-o", "out.png"});
    CHECK(missing.exit_code == 2);
    CHECK(missing.err.find("absent.json") != std::string::npos);
    CHECK(slurp(dir / "out.png") == "precious");
    CHECK_FALSE(fs::exists(dir / "out.jpg"));
    CHECK_FALSE(fs::exists(dir / "ball.png"));
}

TEST_CASE("render cli: Ctrl-C writes the finished samples, says so, and exits 130", "[render][cli][cancel]") {
    const fs::path dir = fresh_dir("interrupt");
    // Too many samples to finish: the test interrupts at the first progress line (10%).
    write_scene(dir / "ball.json", 1 << 20);
    bool sent = false;
    const Run r = run_in(dir, {"render", "ball.json", "--width", "8", "-o", "partial.exr"},
                         [&](const std::string& line, pid_t pid) {
                             if (!sent && line.rfind("render: ", 0) == 0) {
                                 kill(pid, SIGINT);
                                 sent = true;
                             }
                         });
    INFO(r.err);
    REQUIRE(sent);
    CHECK(r.exit_code == 130);
    CHECK(r.err.find("interrupted") != std::string::npos);
    const sweeptrace::Image img = sweeptrace::read_image(dir / "partial.exr");
    CHECK(img.width == 8);
    CHECK(img.height == 4);
    for (const auto& p : img.pixels) CHECK(p.g > 0.0f);  // every pixel has samples (sky or sphere)
    // Nothing but the image is left behind (no temporary files).
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    CHECK(files == 2);
}

TEST_CASE("render cli: film.exposure and tone_curve change only 8-bit output, a flipped light is warned about", "[render][cli][display]") {
    const fs::path dir = fresh_dir("display");
    auto write = [&](const std::string& name, const std::string& film_extra, const std::string& light_edges) {
        std::ofstream(dir / name) << R"({
  "camera": { "position": [0, 1, 4], "look_at": [0, 0.5, 0] },
  "film": { "width": 12, "height": 8, "spp": 2 )" << film_extra << R"( },
  "materials": { "m": { "type": "diffuse", "albedo": [0.6, 0.5, 0.4] },
                 "lamp": { "type": "emissive", "emission": [4, 4, 4] } },
  "objects": [ { "type": "quad", "corner": [-2, 0, -2], "edge_u": [0, 0, 4], "edge_v": [4, 0, 0], "material": "m" },
               { "type": "quad", "corner": [-0.5, 2, -0.5], )" << light_edges << R"(, "material": "lamp" } ]
})";
    };
    const std::string down = R"("edge_u": [1, 0, 0], "edge_v": [0, 0, 1])", up = R"("edge_u": [0, 0, 1], "edge_v": [1, 0, 0])";
    write("plain.json", "", down);
    write("bright.json", R"(, "exposure": 2, "tone_curve": "aces")", down);
    write("flipped.json", "", up);
    for (const char* n : {"plain", "bright"}) {
        const Run r = run_in(dir, {"render", std::string(n) + ".json", "--quiet", "-o", std::string(n) + ".pfm"});
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        CHECK(r.err.empty());
        REQUIRE(run_in(dir, {"render", std::string(n) + ".json", "--quiet", "-o", std::string(n) + ".png"}).exit_code == 0);
    }
    CHECK(slurp(dir / "plain.pfm") == slurp(dir / "bright.pfm"));  // linear output untouched
    CHECK(slurp(dir / "plain.png") != slurp(dir / "bright.png"));
    const Run f = run_in(dir, {"render", "flipped.json", "--quiet", "-o", "flipped.png"});
    CHECK(f.exit_code == 0);
    CHECK(f.err.find("sweeptrace: warning: flipped.json: objects[1] (quad): one-sided emitter") != std::string::npos);
    CHECK(fs::exists(dir / "flipped.png"));
}

TEST_CASE("render cli: bdpt and vcm say that a scene's clamp_indirect and guiding are the path tracer's and not applied, and path stays silent", "[render][cli][bdpt]") {
    const fs::path dir = fresh_dir("bdpt-ignored-settings");
    std::ofstream(dir / "clamped.json") << R"({
  "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 40 },
  "film": { "width": 8, "height": 4, "spp": 2, "max_depth": 3, "clamp_indirect": 5, "guiding": true },
  "materials": { "m": { "type": "diffuse", "albedo": [0.6, 0.5, 0.4] },
                 "lamp": { "type": "emissive", "emission": [4, 4, 4] } },
  "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" },
               { "type": "sphere", "center": [0, 3, 0], "radius": 0.5, "material": "lamp" } ]
})";
    const Run bd = run_in(dir, {"render", "clamped.json", "--quiet", "--integrator", "bdpt", "-o", "b.pfm"});
    INFO(bd.err);
    REQUIRE(bd.exit_code == 0);
    CHECK(bd.err.find("warning: clamped.json: film.clamp_indirect 5 is the path tracer's; bdpt ignores it") != std::string::npos);
    CHECK(bd.err.find("warning: clamped.json: film.guiding is the path tracer's; bdpt renders unguided") != std::string::npos);
    const Run vc = run_in(dir, {"render", "clamped.json", "--quiet", "--integrator", "vcm", "-o", "v.pfm"});
    INFO(vc.err);
    REQUIRE(vc.exit_code == 0);
    CHECK(vc.err.find("warning: clamped.json: film.clamp_indirect 5 is the path tracer's; vcm ignores it") != std::string::npos);
    const Run pt = run_in(dir, {"render", "clamped.json", "--quiet", "--integrator", "path", "-o", "p.pfm"});
    INFO(pt.err);
    REQUIRE(pt.exit_code == 0);
    CHECK(pt.err.empty());
    const Run fx = run_in(dir, {"render", "clamped.json", "--quiet", "--integrator", "bdpt", "--forensics", "f.json"});
    CHECK(fx.exit_code == 2);
    CHECK(fx.err == "sweeptrace: error: --forensics needs the path integrator: it follows a camera path's vertices, and "
                    "the light paths of bdpt and vcm have none of them\n");
    CHECK(!fs::exists(dir / "f.json"));
}

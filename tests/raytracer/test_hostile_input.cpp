// The promises about hostile input that the bad-input corpus (tests/bad_input) cannot show from
// one command and its exit code: SIGTERM keeps the finished samples like SIGINT; temporary files
// are removed by a second signal and swept when their writer is dead; OBJ results do not depend
// on line endings; the command line and the scene file share one range per film setting;
// messages stay one bounded line whatever they quote; a cancel stops a deep bdpt or vcm pass
// inside its first sample; vcm's radius range renders finite at both ends; reference-check's
// stdout escapes the names it prints.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "raytracer/accel/accel.hpp"
#include "cancel_at_ray.hpp"
#include "raytracer/cli/render_limits.hpp"
#include "raytracer/image/atomic_file.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/film_limits.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/obj_loader.hpp"
#include "scene_test_files.hpp"

namespace fs = std::filesystem;
using sweeptrace::test::TempDir;

namespace {

// Runs the binary in `dir`; on its first stderr line starting with "render: " sends `sig`.
// Returns the exit code (128 + signal for a death by signal) and stderr.
std::pair<int, std::string> run_and_signal(const fs::path& dir, std::vector<std::string> args, int sig) {
    int pipefd[2];
    REQUIRE(pipe(pipefd) == 0);
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        dup2(pipefd[1], STDERR_FILENO);
        close(pipefd[0]);
        close(pipefd[1]);
        if (chdir(dir.c_str()) != 0) _exit(99);
        std::string bin = (fs::path(SWEEPTRACE_BINARY_DIR) / "sweeptrace").string();
        std::vector<char*> argv{bin.data()};
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(bin.c_str(), argv.data());
        _exit(98);
    }
    close(pipefd[1]);
    std::string err;
    bool sent = false;
    char c;
    while (read(pipefd[0], &c, 1) == 1) {
        err.push_back(c);
        if (!sent && c == '\n' && err.find("render: ") != std::string::npos) {
            kill(pid, sig);
            sent = true;
        }
    }
    close(pipefd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    REQUIRE(sent);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), err};
}

const char* kSphereScene = R"({
  "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0] },
  "film": { "width": 8, "height": 4, "spp": 1048576 },
  "background": { "color": [1, 1, 1] },
  "materials": { "m": { "type": "diffuse" } },
  "objects": [ { "type": "sphere", "radius": 1, "material": "m" } ]
})";

}  // namespace

TEST_CASE("hostile input: SIGTERM writes the finished samples like Ctrl-C and exits 143", "[cli][cancel]") {
    const TempDir dir;
    dir.write("ball.json", kSphereScene);
    const auto [code, err] = run_and_signal(dir.path(), {"render", "ball.json", "-o", "partial.pfm"}, SIGTERM);
    INFO(err);
    CHECK(code == 143);
    CHECK(err.find("interrupted: wrote partial.pfm") != std::string::npos);
    const sweeptrace::Image img = sweeptrace::read_image(dir.path() / "partial.pfm");
    CHECK(img.width == 8);
    for (const auto& p : img.pixels) CHECK(p.g > 0.0f);
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir.path())) files += e.is_regular_file();
    CHECK(files == 2);  // the scene and the image: no temporary left behind
}

TEST_CASE("hostile input: a write interrupted for good removes its temporary file", "[image][atomic]") {
    const TempDir dir;
    const fs::path out = dir.path() / "x.png";
    fs::path seen;
    // What the second signal's handler does, called from inside the write.
    CHECK_THROWS_AS(sweeptrace::write_atomically(out, [&](const fs::path& temp) {
                        seen = temp;
                        REQUIRE(fs::exists(temp));
                        sweeptrace::remove_temporaries_in_progress();
                    }),
                    sweeptrace::InputError);
    CHECK_FALSE(seen.empty());
    CHECK_FALSE(fs::exists(seen));
    CHECK_FALSE(fs::exists(out));
}

TEST_CASE("hostile input: stale temporaries of dead writers are swept at the next write, live ones kept", "[image][atomic]") {
    const TempDir dir;
    const pid_t child = fork();
    if (child == 0) _exit(0);
    REQUIRE(child > 0);
    waitpid(child, nullptr, 0);  // now certainly not running
    const fs::path dead = dir.write(".x.png.tmp-" + std::to_string(child) + "-7", "partial");
    const fs::path live = dir.write(".x.png.tmp-" + std::to_string(getppid()) + "-0", "someone else's");
    const fs::path other = dir.write(".y.png.tmp-" + std::to_string(child) + "-0", "another file's");
    const fs::path odd = dir.write(".x.png.tmp-notapid", "not ours");
    sweeptrace::write_atomically(dir.path() / "x.png", [](const fs::path& temp) { std::ofstream(temp) << "new"; });
    CHECK_FALSE(fs::exists(dead));
    CHECK(fs::exists(live));
    CHECK(fs::exists(other));  // swept only when y.png is written
    CHECK(fs::exists(odd));
    CHECK(fs::exists(dir.path() / "x.png"));
}

TEST_CASE("hostile input: an OBJ gives the same mesh with LF, CRLF or CR line endings", "[scene][obj]") {
    const std::string lf =
        "# a quad and a pentagon\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 2 0\nvn 0 0 1\n\n"
        "f 1//1 2//1 3//1 4//1\nf 4//1 3//1 5//1 1//1 2//1\n";
    auto with = [&](const std::string& eol) {
        std::string s;
        for (char c : lf) s += c == '\n' ? eol : std::string(1, c);
        return s;
    };
    const TempDir dir;
    const sweeptrace::Mesh ref = sweeptrace::load_obj(dir.write("lf.obj", lf));
    for (const std::string eol : {"\r\n", "\r"}) {
        const sweeptrace::Mesh m = sweeptrace::load_obj(dir.write("other.obj", with(eol)));
        CHECK(m.triangles.vertices == ref.triangles.vertices);
        CHECK(m.triangles.indices == ref.triangles.indices);
        CHECK(m.vertex_normals == ref.vertex_normals);
    }
    CHECK(ref.triangles.indices.size() == 5);  // 2 + 3 fan triangles
    // And a bad face is reported on the same line whatever the endings.
    for (const std::string eol : {"\n", "\r\n", "\r"}) {
        const std::string bad = "v 0 0 0" + eol + "v 1 0 0" + eol + eol + "v 0 1 0" + eol + "f 1 2 7" + eol;
        CHECK_THROWS_WITH(sweeptrace::load_obj(dir.write("bad.obj", bad)), Catch::Contains("line 5: vertex index out of range"));
    }
}

TEST_CASE("hostile input: each film setting has one range, the same from the scene file and the command line", "[cli][scene]") {
    using sweeptrace::FilmSetting;
    const TempDir dir;
    const struct {
        FilmSetting setting;
        const char* key;
        const char* option;
    } settings[] = {{FilmSetting::Width, "width", "--width"},
                    {FilmSetting::Height, "height", "--height"},
                    {FilmSetting::Spp, "spp", "--spp"},
                    {FilmSetting::MaxDepth, "max_depth", "--max-depth"}};
    for (const auto& s : settings) {
        const sweeptrace::SettingRange r = sweeptrace::film_range(s.setting);
        for (const std::int64_t v : {r.lo - 1, r.lo, r.hi, r.hi + 1, std::int64_t{-1}}) {
            std::string film = R"({"width": 8, "height": 8, "spp": 1, "max_depth": 2})";
            film.replace(film.find(std::string("\"") + s.key + "\"") + std::string(s.key).size() + 4, 1, std::to_string(v));
            // Both sides given for the size settings, so no aspect ratio is derived.
            const std::string scene_text = R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "film": )" +
                                           film + R"(, "materials": {"m": {"type": "diffuse"}}, "objects": []})";
            bool scene_ok = true;
            try {
                sweeptrace::load_scene(dir.write("s.json", scene_text));
            } catch (const sweeptrace::InputError&) {
                scene_ok = false;
            }
            CLI::App app;
            sweeptrace::RenderLimits limits;
            limits.add_options(app);
            std::vector<std::string> args = {std::to_string(v), s.option};  // CLI11 parses a reversed vector
            if (s.setting == FilmSetting::Width) args.insert(args.begin(), {"8", "--height"});
            if (s.setting == FilmSetting::Height) args.insert(args.begin(), {"8", "--width"});
            app.parse(args);
            bool cli_ok = true;
            sweeptrace::Scene scene;
            try {
                limits.validate();
                limits.apply(scene);
            } catch (const sweeptrace::InputError&) {
                cli_ok = false;
            }
            INFO(s.key << " = " << v);
            CHECK(scene_ok == cli_ok);
            CHECK(cli_ok == (v >= r.lo && v <= r.hi));
        }
    }
}

TEST_CASE("hostile input: a message is one line of bounded length whatever it quotes", "[input]") {
    const std::string huge(200000, 'k');
    const sweeptrace::InputError e("scene.json: objects[0]." + huge + ": unknown key\nsecond line\r");
    const std::string what = e.what();
    CHECK(what.size() <= sweeptrace::InputError::kMaxMessage);
    CHECK(what.find('\n') == std::string::npos);
    CHECK(what.find('\r') == std::string::npos);
    CHECK(what.rfind("scene.json: objects[0].kkk", 0) == 0);  // keeps the file and the place
    CHECK(what.find("...") != std::string::npos);
    // Cuts fall between UTF-8 characters: no continuation byte right after the head or before
    // the tail ("é" is 2 bytes, so an odd cut would split one).
    std::string accents;
    for (int i = 0; i < 100; ++i) accents += "\xc3\xa9";
    for (const std::size_t max : {7u, 8u, 9u, 40u, 41u}) {
        const std::string e = sweeptrace::excerpt(accents, max);
        INFO(max << ": " << e);
        CHECK(e.size() <= max);
        for (std::size_t i = 0; i < e.size(); ++i)
            if ((static_cast<unsigned char>(e[i]) & 0xC0) == 0x80) CHECK((static_cast<unsigned char>(e[i - 1]) & 0xE0) == 0xC0);
        CHECK((static_cast<unsigned char>(e.back()) & 0xE0) != 0xC0);  // no lead byte left without its partner
    }
    CHECK(sweeptrace::reason_or("", "fallback") == "fallback");
    CHECK(sweeptrace::reason_or("Success", "fallback") == "fallback");
    CHECK(sweeptrace::reason_or(nullptr, "fallback") == "fallback");
}

namespace {

// A closed white box (albedo 1: no path is ever ended by roulette) with a lamp, seen from inside:
// every bdpt sample walks max_depth vertices each way and joins them all.
const char* kWhiteBox = R"({
  "camera": { "position": [0, 0, 0.5], "look_at": [0, 0, -1] },
  "film": { "width": 2, "height": 2, "spp": 4, "max_depth": 256 },
  "materials": { "white": { "type": "diffuse", "albedo": [1, 1, 1] },
                 "lamp": { "type": "diffuse", "albedo": [1, 1, 1], "emission": [1, 1, 1] } },
  "objects": [ { "type": "box", "center": [0, 0, 0], "size": [4, 4, 4], "material": "white" },
               { "type": "sphere", "center": [0, 1, -1], "radius": 0.2, "material": "lamp" } ]
})";

bool same_bits(const sweeptrace::Image& a, const sweeptrace::Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

// kWhiteBox with `from` replaced by `to`.
std::string white_box_with(const std::string& from, const std::string& to) {
    std::string text = kWhiteBox;
    return text.replace(text.find(from), from.size(), to);
}

}  // namespace

TEST_CASE("hostile input: a cancel inside a deep bdpt or vcm pass stops within its first sample, the finished passes kept",
          "[render][cancel]") {
    const TempDir dir;
    const sweeptrace::Scene scene = sweeptrace::load_scene(dir.write("box.json", kWhiteBox));
    const auto accel = sweeptrace::make_accel(sweeptrace::AccelKind::Bvh, scene);
    for (const auto integrator : {sweeptrace::IntegratorKind::Bdpt, sweeptrace::IntegratorKind::Vcm}) {
        sweeptrace::RenderOptions o;
        o.integrator = integrator;
        o.max_depth = scene.film.max_depth;
        o.threads = 1;  // the rays are then counted in one fixed order
        o.seed = 3;
        std::atomic<bool> never{false};
        o.spp = 1;
        const sweeptrace::test::CancelAtRay counter(*accel, never, 0);
        const sweeptrace::RenderResult one = sweeptrace::render(scene, counter, o);
        const std::uint64_t pass = counter.rays();  // one pass: 4 samples of ~10^5 rays each
        // The flag goes up 10 rays into the second pass: its first sample's camera walk.
        std::atomic<bool> cancel{false};
        const sweeptrace::test::CancelAtRay cancelling(*accel, cancel, pass + 10);
        o.spp = 4;
        o.cancel = &cancel;
        const sweeptrace::RenderResult r = sweeptrace::render(scene, cancelling, o);
        INFO("integrator " << sweeptrace::integrator_name(integrator) << ": a pass is " << pass << " rays, "
                           << cancelling.rays() - (pass + 10) << " traced after the cancel");
        CHECK(r.stats.cancelled);
        CHECK(r.stats.completed_spp == 1);
        CHECK(same_bits(r.image, one.image));  // the finished pass, bit for bit; the cut one dropped
        // Checked per sample only, the cut sample would run to its end: a quarter of a pass. Inside
        // its strategy loops it stops after the walks and at most one camera vertex's connections.
        CHECK(cancelling.rays() - (pass + 10) < pass / 40);
    }
}

TEST_CASE("hostile input: vcm renders finite images at both ends of the radius range the loader accepts", "[render][vcm]") {
    const TempDir dir;
    const sweeptrace::RadiusRange range = sweeptrace::vcm_radius_range();
    for (const float radius : {range.lo, range.hi}) {
        char text[64];
        std::snprintf(text, sizeof text, "%.9g", double(radius));
        const sweeptrace::Scene scene = sweeptrace::load_scene(
            dir.write("box.json", white_box_with("\"max_depth\": 256", std::string("\"max_depth\": 4, \"vcm_radius\": ") + text)));
        const auto accel = sweeptrace::make_accel(sweeptrace::AccelKind::Bvh, scene);
        sweeptrace::RenderOptions o;
        o.integrator = sweeptrace::IntegratorKind::Vcm;
        o.max_depth = 4;
        o.threads = 1;
        o.spp = 1;
        for (const int iteration : {0, (1 << 20) - 1}) {  // the first radius, and the last the spp limit reaches
            o.first_sample = iteration;
            const sweeptrace::RenderResult r = sweeptrace::render(scene, *accel, o);
            INFO("radius " << text << ", iteration " << iteration);
            CHECK(r.stats.nonfinite_samples == 0u);
            for (const glm::vec3& p : r.image.pixels) CHECK((std::isfinite(p.x) && p.x > 0.0f));
        }
    }
    CHECK_THROWS_AS(sweeptrace::load_scene(dir.write("s.json", white_box_with("\"spp\": 4", "\"spp\": 4, \"vcm_radius\": 1e20"))),
                    sweeptrace::InputError);
}

TEST_CASE("hostile input: reference-check escapes the scene names it prints", "[cli][reference-check]") {
    const TempDir dir;
    // A subfolder whose name would recolour a terminal and forge an error line.
    const std::string name = "a\x1b[31mb\nsweeptrace: error: forged";
    dir.write("F/" + name + "/scene-v4.pbrt",
              "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n"
              "LightSource \"distant\" \"point3 from\" [0 0 1] \"point3 to\" [0 0 0]\nShape \"sphere\"\n");
    sweeptrace::Image ref(8, 8);
    for (glm::vec3& p : ref.pixels) p = glm::vec3(0.5f);
    sweeptrace::write_image(ref, dir.path() / "F" / name / "TungstenRender.exr");
    const std::string binary = (fs::path(SWEEPTRACE_BINARY_DIR) / "sweeptrace").string();
    const std::string cmd = "cd '" + dir.path().string() + "' && '" + binary +
                            "' reference-check F --spp 2 --downsample 1 > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    std::ifstream in(dir.path() / "out.txt");
    const std::string out{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    INFO(out);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) <= 1);  // judged (it need not match at 2 spp), not refused
    CHECK(out.find("mean ratio") != std::string::npos);
    CHECK(out.find('\x1b') == std::string::npos);
    CHECK(out.find("\nsweeptrace: error: forged") == std::string::npos);
    CHECK(out.find("a\\x1b[31mb\\nsweeptrace: error: forged") != std::string::npos);
}

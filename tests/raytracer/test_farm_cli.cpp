// The farm as a user runs it: `render --samples A:B` parts merged by `sweeptrace merge` are the
// same FILE, byte for byte, as `render --spp N` writes (PNG, EXR, PFM; several splits, uneven and
// single-sample parts); the merge's refusals exit 2 with one `sweeptrace: error:` line and write
// nothing; --skip-existing keeps a verified part and redoes a damaged one.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kBinary = fs::path(SWEEPTRACE_BINARY_DIR) / "sweeptrace";

struct Run {
    int exit_code = -1;
    std::string err;
};

std::string slurp(const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Runs the binary in `dir` with `args` (already shell-quoted where needed), stderr captured.
Run run(const fs::path& dir, const std::string& args) {
    const std::string cmd = "cd '" + dir.string() + "' && '" + kBinary.string() + "' " + args + " 2> stderr.txt";
    const int status = std::system(cmd.c_str());
    Run r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    r.err = slurp(dir / "stderr.txt");
    return r;
}

fs::path fresh_dir(const std::string& name) {
    const fs::path d = fs::path(SWEEPTRACE_BINARY_DIR) / "farm-cli-tests" / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

// A 24x16 scene: a glass sphere and a diffuse one under a sky, light enough to render 40 times.
void write_scene(const fs::path& file, const std::string& albedo = "0.6, 0.5, 0.4") {
    std::ofstream(file) << R"({
  "camera": { "position": [0, 0.5, 5], "look_at": [0, 0, 0], "fov": 40 },
  "film": { "width": 24, "height": 16, "spp": 9, "max_depth": 5 },
  "background": { "sky": { "horizon": [1, 1, 1], "zenith": [0.3, 0.5, 1] } },
  "materials": { "m": { "type": "diffuse", "albedo": [)" << albedo << R"(] },
                 "g": { "type": "dielectric", "ior": 1.5 } },
  "objects": [ { "type": "sphere", "center": [-0.8, 0, 0], "radius": 0.7, "material": "m" },
               { "type": "sphere", "center": [0.8, 0, 0], "radius": 0.7, "material": "g" } ]
})";
}

// Renders the parts of `cuts` (sample boundaries from 0 to 9) and merges them to `out`.
Run render_and_merge(const fs::path& dir, const std::vector<int>& cuts, const std::string& out) {
    std::string parts;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const std::string name = "part" + std::to_string(i) + ".exr";
        const std::string threads = std::to_string(1 + i % 2);
        const Run r = run(dir, "render scene.json --quiet --threads " + threads + " --samples " + std::to_string(cuts[i]) +
                                   ":" + std::to_string(cuts[i + 1]) + " -o " + name);
        if (r.exit_code != 0) return r;
        parts = name + " " + parts;  // listed last part first: the merge orders them
    }
    return run(dir, "merge --quiet " + parts + "-o " + out);
}

void check_refused(const fs::path& dir, const Run& r, const std::string& message_part) {
    INFO(r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.rfind("sweeptrace: error: ", 0) == 0);
    CHECK(r.err.find('\n') == r.err.size() - 1);  // one line
    CHECK(r.err.find(message_part) != std::string::npos);
    CHECK(slurp(dir / "final.png") == "the previous image");  // nothing written over it
    CHECK_FALSE(fs::exists(dir / "new.exr"));
}

}  // namespace

TEST_CASE("farm cli: merged parts are the single render's file byte for byte, for any split", "[farm][cli]") {
    const fs::path dir = fresh_dir("identity");
    write_scene(dir / "scene.json");
    for (const std::string ext : {".png", ".exr", ".pfm"}) {
        const Run one = run(dir, "render scene.json --quiet --threads 2 -o one" + ext);
        REQUIRE(one.exit_code == 0);
        const std::string expected = slurp(dir / ("one" + ext));
        REQUIRE(!expected.empty());
        const std::vector<std::vector<int>> splits =
            ext == ".png" ? std::vector<std::vector<int>>{{0, 9}, {0, 4, 5, 9}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}}
                          : std::vector<std::vector<int>>{{0, 2, 9}};
        for (const auto& cuts : splits) {
            const Run m = render_and_merge(dir, cuts, "merged" + ext);
            INFO(ext << ", " << cuts.size() - 1 << " parts: " << m.err);
            REQUIRE(m.exit_code == 0);
            CHECK(slurp(dir / ("merged" + ext)) == expected);
            fs::remove(dir / ("merged" + ext));
        }
    }
}

TEST_CASE("farm cli: merge refuses other renders, overlaps and gaps, exit 2, nothing written", "[farm][cli]") {
    const fs::path dir = fresh_dir("refusals");
    write_scene(dir / "scene.json");
    std::ofstream(dir / "final.png") << "the previous image";
    const auto part = [&](const std::string& range, const std::string& name, const std::string& extra = "") {
        REQUIRE(run(dir, "render scene.json --quiet --samples " + range + " -o " + name + " " + extra).exit_code == 0);
    };
    part("0:4", "a.exr");
    part("4:9", "b.exr");
    part("3:9", "c.exr");
    part("4:9", "seed.exr", "--seed 7");
    part("4:9", "small.exr", "--width 12");
    part("4:9", "deep.exr", "--max-depth 3");
    part("4:9", "embree.exr", "--accel embree");
    part("4:9", "independent.exr", "--sampler independent");
    write_scene(dir / "scene.json", "0.6, 0.5, 0.41");  // one number of the scene changed
    part("4:9", "edited.exr");

    check_refused(dir, run(dir, "merge a.exr -o final.png"), "samples [4, 9) of the 9-sample render are missing");
    check_refused(dir, run(dir, "merge b.exr -o new.exr"), "samples [0, 4) of the 9-sample render are missing");
    check_refused(dir, run(dir, "merge a.exr c.exr -o final.png"),
                  "parts 'a.exr' [0, 4) and 'c.exr' [3, 9) overlap on samples [3, 4)");
    check_refused(dir, run(dir, "merge a.exr b.exr b.exr -o final.png"), "overlap on samples [4, 9)");
    check_refused(dir, run(dir, "merge a.exr seed.exr -o final.png"),
                  "'seed.exr' is not a part of the same render as 'a.exr': seed 0 vs 7");
    check_refused(dir, run(dir, "merge a.exr small.exr -o final.png"), "width 24 vs 12");
    check_refused(dir, run(dir, "merge a.exr deep.exr -o final.png"), "max depth 5 vs 3");
    check_refused(dir, run(dir, "merge a.exr embree.exr -o final.png"), "accel 'bvh' vs 'embree'");
    check_refused(dir, run(dir, "merge a.exr independent.exr -o final.png"),
                  "'independent.exr' is not a part of the same render as 'a.exr': sampler 'sobol' vs 'independent'");
    check_refused(dir, run(dir, "merge a.exr edited.exr -o final.png"), "scene hash");
    REQUIRE(run(dir, "render scene.json --quiet -o plain.exr").exit_code == 0);
    check_refused(dir, run(dir, "merge a.exr plain.exr -o final.png"), "'plain.exr': not a sweeptrace part");
    check_refused(dir, run(dir, "merge a.exr missing.exr -o final.png"), "missing.exr");
    std::string damaged = slurp(dir / "b.exr");
    damaged[damaged.size() / 2] = static_cast<char>(damaged[damaged.size() / 2] ^ 0x10);
    std::ofstream(dir / "damaged.exr", std::ios::binary) << damaged;
    check_refused(dir, run(dir, "merge a.exr damaged.exr -o final.png"), "'damaged.exr'");
    check_refused(dir, run(dir, "merge a.exr b.exr -o final.jpg"), "unknown image extension '.jpg'");
    check_refused(dir, run(dir, "render scene.json --samples 4:10 -o new.exr"), "need 0 <= A < B <= spp (9");
    check_refused(dir, run(dir, "render scene.json --samples 4 -o new.exr"), "expected A:B");
    check_refused(dir, run(dir, "render scene.json --samples 0:4 -o final.png"), "an .exr file");
    // A part is exactly its range of a whole render: no time budget, no guide trained on passes
    // the part does not render.
    check_refused(dir, run(dir, "render scene.json --samples 4:9 --time 5 -o new.exr"), "--samples and --time");
    check_refused(dir, run(dir, "render scene.json --samples 4:9 --guiding on -o new.exr"), "--guiding off");
}

TEST_CASE("farm cli: --skip-existing keeps a verified part and redoes a damaged one", "[farm][cli]") {
    const fs::path dir = fresh_dir("skip");
    write_scene(dir / "scene.json");
    REQUIRE(run(dir, "render scene.json --quiet --samples 2:5 -o p.exr").exit_code == 0);
    const std::string good = slurp(dir / "p.exr");
    const auto written = fs::last_write_time(dir / "p.exr");

    Run r = run(dir, "render scene.json --samples 2:5 -o p.exr --skip-existing");
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.find("already a verified part of this render, kept") != std::string::npos);
    CHECK(fs::last_write_time(dir / "p.exr") == written);

    // The same file asked for another range, or damaged: rendered again.
    std::string damaged = good;
    damaged[damaged.size() / 2] = static_cast<char>(damaged[damaged.size() / 2] ^ 0x10);
    std::ofstream(dir / "p.exr", std::ios::binary) << damaged;
    r = run(dir, "render scene.json --quiet --samples 2:5 -o p.exr --skip-existing");
    CHECK(r.exit_code == 0);
    CHECK(slurp(dir / "p.exr") == good);
    r = run(dir, "render scene.json --quiet --samples 2:6 -o p.exr --skip-existing");
    CHECK(r.exit_code == 0);
    CHECK(slurp(dir / "p.exr") != good);
}

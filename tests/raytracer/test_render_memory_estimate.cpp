// The render's memory estimate (cli/memory_budget.hpp) counts what each integrator and sampling
// mode keeps per pixel: a vcm light subpath per pixel, adaptive sampling's counts and round sums, the feature outputs' exact sums,
// bdpt's and vcm's light splats for a wave of tiles, --forensics' regions,
// so --max-memory refuses before the allocation rather than after it. And what the binary takes
// holds to it: the peak memory bdpt, vcm and --forensics add to a render is within what the
// estimate charges them.
#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include <glm/vec3.hpp>

#include "raytracer/cli/memory_budget.hpp"
#include "raytracer/image/feature_sums.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/film/film_splats.hpp"
#include "raytracer/render/integrators/light_vertices.hpp"
#include "raytracer/render/film/path_forensics.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;

namespace {

Scene memory_estimate_scene(IntegratorKind integrator) {
    Scene s;
    s.film.width = 64;
    s.film.height = 32;
    s.film.max_depth = 8;
    s.film.integrator = integrator;
    return s;
}

// The peak-memory checks below measure the program's resident peak, which AddressSanitizer's
// allocator changes (freed blocks wait in a quarantine of up to 256 MB before reuse).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// The binary run in `dir` with `args` under a 1 GiB address-space limit (a guard: an unbounded
// allocation fails there instead of taking a shared machine's memory; these renders need under
// 100 MB): its exit code and peak resident memory.
struct PeakRun {
    int exit_code = -1;
    std::uint64_t peak_bytes = 0;
};
PeakRun run_for_peak(const std::filesystem::path& dir, const std::string& args) {
    const std::string binary = (std::filesystem::path(SWEEPTRACE_BINARY_DIR) / "sweeptrace").string();
    const std::string cmd =
        "cd '" + dir.string() + "' && ulimit -v 1048576 && exec '" + binary + "' " + args + " > /dev/null 2> stderr.txt";
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    REQUIRE(wait4(pid, &status, 0, &usage) == pid);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, static_cast<std::uint64_t>(usage.ru_maxrss) * 1024};
}

}  // namespace

TEST_CASE("render memory estimate: vcm's light subpaths and adaptive sampling's per-pixel state are counted", "[cli][memory]") {
    const Scene path = memory_estimate_scene(IntegratorKind::Path);
    const Scene vcm = memory_estimate_scene(IntegratorKind::Vcm);
    const std::uint64_t pixels = 64 * 32;
    const MemoryEstimate base = estimate_render_memory(path);
    CHECK(estimate_render_memory(memory_estimate_scene(IntegratorKind::Bdpt)).film == base.film);
    // vcm: at least one photon per light-subpath vertex, max_depth of them per pixel.
    CHECK(estimate_render_memory(vcm).film >= base.film + pixels * 8 * sizeof(Photon));
    const MemoryEstimate adaptive = estimate_render_memory(path, true);
    CHECK(adaptive.film > base.film);
    CHECK((adaptive.film - base.film) % pixels == 0);  // a cost per pixel
    CHECK(adaptive.scene == base.scene);
    // The limit between the two estimates refuses the adaptive render alone.
    const std::uint64_t limit = base.total() + (adaptive.total() - base.total()) / 2;
    CHECK_NOTHROW(check_render_memory(path, limit));
    CHECK_THROWS_AS(check_render_memory(path, limit, true), InputError);
}

TEST_CASE("render memory estimate: feature outputs' exact sums are counted, more under adaptive sampling", "[cli][memory][aovs]") {
    const Scene plain = memory_estimate_scene(IntegratorKind::Path);
    Scene aovs = plain;
    aovs.film.aovs = true;
    const std::uint64_t pixels = 64 * 32;
    const MemoryEstimate base = estimate_render_memory(plain);
    // At least the renderer's sums (the colour and three features by half, squares) per pixel.
    CHECK(estimate_render_memory(aovs).film >= base.film + pixels * sizeof(FeatureSums));
    CHECK(estimate_render_memory(aovs, true).film >= estimate_render_memory(plain, true).film + 3 * pixels * sizeof(FeatureSums));
    const std::uint64_t limit = base.total() + (estimate_render_memory(aovs).total() - base.total()) / 2;
    CHECK_NOTHROW(check_render_memory(plain, limit));
    CHECK_THROWS_AS(check_render_memory(aovs, limit), InputError);
}

TEST_CASE("render memory estimate: bdpt's and vcm's light splats are charged for one wave of tiles, whatever the filter",
          "[cli][memory]") {
    const Scene path = memory_estimate_scene(IntegratorKind::Path);
    Scene bdpt = memory_estimate_scene(IntegratorKind::Bdpt);
    CHECK(estimate_render_memory(path).splats == 0);
    // 64 x 32 pixels, depth 8: every pixel's sample makes at most 8 splats of 20 bytes, kept in
    // vectors under twice their size; and the pass's sum of splats per pixel.
    const std::uint64_t sums = 64 * 32 * sizeof(glm::vec3);
    CHECK(estimate_render_memory(bdpt).splats == sums + 64 * 32 * 8 * sizeof(Splat) * 2);
    CHECK(estimate_render_memory(memory_estimate_scene(IntegratorKind::Vcm)).splats == estimate_render_memory(bdpt).splats);
    bdpt.film.filter.radius = 16.0f;  // a splat is one entry at any filter size
    CHECK(estimate_render_memory(bdpt).splats == sums + 64 * 32 * 8 * sizeof(Splat) * 2);
    // A larger image: one wave of 64 tiles of 16 x 16 pixels, not the image.
    bdpt.film.width = bdpt.film.height = 4096;
    CHECK(estimate_render_memory(bdpt).splats == 4096 * 4096 * sizeof(glm::vec3) + 64 * 256 * 8 * sizeof(Splat) * 2);
    const std::uint64_t limit = estimate_render_memory(path).total() + estimate_render_memory(memory_estimate_scene(IntegratorKind::Bdpt)).splats / 2;
    CHECK_NOTHROW(check_render_memory(path, limit));
    CHECK_THROWS_AS(check_render_memory(memory_estimate_scene(IntegratorKind::Bdpt), limit), InputError);
}

TEST_CASE("render memory estimate: --forensics is charged per region, not per sample", "[cli][memory][forensics]") {
    const Scene path = memory_estimate_scene(IntegratorKind::Path);
    const MemoryEstimate off = estimate_render_memory(path);
    const MemoryEstimate on = estimate_render_memory(path, false, true);
    CHECK(off.forensics == 0);
    CHECK(on.forensics == PathForensics::memory_bytes(64, 32));
    // 8 regions of 16 x 16, each at least its kept keys' sums twice (the totals, the pass in flight).
    CHECK(on.forensics >= 8 * 2 * (PathForensics::kRegionTypes + 1) * sizeof(PathMoments));
    Scene more_spp = path;
    more_spp.film.spp = 1 << 20;
    CHECK(estimate_render_memory(more_spp, false, true).forensics == on.forensics);
    const std::uint64_t limit = off.total() + on.forensics / 2;
    CHECK_NOTHROW(check_render_memory(path, limit));
    CHECK_THROWS_AS(check_render_memory(path, limit, false, true), InputError);
}

TEST_CASE("render memory estimate: the peak memory bdpt's and vcm's splats add stays within their charge, at a filter of radius 16",
          "[cli][memory]") {
    if (kAddressSanitizer) {
        WARN("skipped under AddressSanitizer: its quarantine keeps freed blocks, so the peak is not the program's own");
        return;
    }
    // A floor, a ball and a lamp, 128 x 128 (one wave of tiles): with the splats spread when made,
    // each light vertex seen by the camera took the 1024 pixels of the filter's footprint.
    const test::TempDir dir;
    const std::filesystem::path file = dir.write("room.json", R"({
  "camera": { "position": [0, 1, 3.5], "look_at": [0, 0.8, 0] },
  "film": { "width": 128, "height": 128, "spp": 1, "max_depth": 8,
            "filter": { "type": "gaussian", "radius": 16, "sigma": 8 } },
  "materials": { "white": { "type": "diffuse", "albedo": [0.8, 0.8, 0.8] },
                 "lamp": { "type": "diffuse", "albedo": [0, 0, 0], "emission": [8, 8, 8] } },
  "objects": [ { "type": "quad", "corner": [-3, 0, -3], "edge_u": [0, 0, 6], "edge_v": [6, 0, 0], "material": "white" },
               { "type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "white" },
               { "type": "sphere", "center": [0, 2.2, 0.5], "radius": 0.2, "material": "lamp" } ]
})");
    Scene scene = load_scene(file);
    const PeakRun path = run_for_peak(dir.path(), "render room.json --integrator path --threads 2 --quiet -o path.pfm");
    REQUIRE(path.exit_code == 0);
    for (const IntegratorKind kind : {IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        const std::string name = integrator_name(kind);
        const PeakRun r = run_for_peak(dir.path(), "render room.json --integrator " + name + " --threads 2 --quiet -o " + name + ".pfm");
        scene.film.integrator = IntegratorKind::Path;
        const std::uint64_t base = estimate_render_memory(scene).total();
        scene.film.integrator = kind;
        const std::uint64_t charged = estimate_render_memory(scene).total() - base;
        INFO(name << ": peak " << r.peak_bytes << " bytes against the path tracer's " << path.peak_bytes << ", charged "
                  << charged << " more");
        REQUIRE(r.exit_code == 0);
        CHECK(r.peak_bytes <= path.peak_bytes + charged);
    }
}

TEST_CASE("render memory estimate: the peak memory --forensics adds stays within its charge when paths make new types at every sample",
          "[cli][memory][forensics]") {
    if (kAddressSanitizer) {
        WARN("skipped under AddressSanitizer: its quarantine keeps freed blocks, so the peak is not the program's own");
        return;
    }
    // A closed box of white walls with a rough and a smooth metal ball (as the forensics tests'
    // mixed box): nearly every long path is a path type of its own. Keeping each, the report grew
    // by 40 MB at 16 spp for this 64 x 64 image.
    const test::TempDir dir;
    dir.write("box.json", R"({
  "camera": { "position": [0, 0, 1.5], "look_at": [0, 0, -1] },
  "film": { "width": 64, "height": 64, "spp": 16, "max_depth": 24 },
  "materials": { "white": { "type": "diffuse", "albedo": [1, 1, 1] },
                 "gloss": { "type": "metal", "albedo": [1, 1, 1], "roughness": 0.3 },
                 "mirror": { "type": "metal", "albedo": [1, 1, 1], "roughness": 0 },
                 "lamp": { "type": "diffuse", "albedo": [1, 1, 1], "emission": [1, 1, 1] } },
  "objects": [ { "type": "box", "center": [0, 0, 0], "size": [4, 4, 4], "material": "white" },
               { "type": "sphere", "center": [1, -1, -1], "radius": 0.5, "material": "gloss" },
               { "type": "sphere", "center": [-1, -1, -1], "radius": 0.5, "material": "mirror" },
               { "type": "sphere", "center": [0, 1, -1], "radius": 0.2, "material": "lamp" } ]
})");
    const PeakRun off = run_for_peak(dir.path(), "render box.json --threads 1 --quiet -o off.pfm");
    const PeakRun on = run_for_peak(dir.path(), "render box.json --threads 1 --quiet -o on.pfm --forensics on.json");
    INFO("peak " << on.peak_bytes << " bytes with --forensics, " << off.peak_bytes << " without, charged "
                 << PathForensics::memory_bytes(64, 64));
    REQUIRE(off.exit_code == 0);
    REQUIRE(on.exit_code == 0);
    CHECK(on.peak_bytes <= off.peak_bytes + PathForensics::memory_bytes(64, 64));
}

// The majorant grid's gain over one global majorant (issue 41, "Speed"), on the sparse smoke of
// scenes/media/smoke.json (written by tools/make_smoke_grid.py): tentative (null and real) collisions
// and CPU time per ratio-tracked and per delta-tracked ray through its box, for the 16^3 majorant
// grid and for a single bound. Hidden (a benchmark: it prints timing); run it by its tag:
//   build/tests/raytracer_tests "[.media-bench]"
// It asserts only the collision counts (at least 3x fewer with the grid), never the times.
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <ctime>

#include "raytracer/render/media/tracking.hpp"
#include "raytracer/scene/load_scene.hpp"

using namespace sweeptrace;

namespace {

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct BenchRun {
    std::uint64_t ratio_collisions = 0, delta_collisions = 0;
    double ratio_seconds = 0.0, delta_seconds = 0.0;
};

// Rays from random points on a sphere around the box toward random points in it.
BenchRun bench_run(const MediumModel& model, int rays) {
    BenchRun r;
    Rng rng(5, 0, 0);
    double t0 = cpu_seconds();
    for (int i = 0; i < rays; ++i) {
        const glm::vec3 target(rng.uniform() * 2.0f - 1.0f, rng.uniform() * 2.0f, rng.uniform() * 2.0f - 1.0f);
        const glm::vec3 from = glm::vec3(0.0f, 1.0f, 0.0f) + 3.0f * uniform_sphere(rng.uniform(), rng.uniform());
        const glm::vec3 d = glm::normalize(target - from);
        ratio_track(model, from, d, 0.0f, 10.0f, rng, &r.ratio_collisions);
    }
    r.ratio_seconds = cpu_seconds() - t0;
    t0 = cpu_seconds();
    for (int i = 0; i < rays; ++i) {
        const glm::vec3 target(rng.uniform() * 2.0f - 1.0f, rng.uniform() * 2.0f, rng.uniform() * 2.0f - 1.0f);
        const glm::vec3 from = glm::vec3(0.0f, 1.0f, 0.0f) + 3.0f * uniform_sphere(rng.uniform(), rng.uniform());
        glm::vec3 beta(1.0f), r_u(1.0f);
        r.delta_collisions += delta_track(model, from, glm::normalize(target - from), 0.0f, 10.0f, 0, rng, beta, r_u, false).collisions;
    }
    r.delta_seconds = cpu_seconds() - t0;
    return r;
}

}  // namespace

TEST_CASE("media bench: the majorant grid against one global majorant on sparse smoke", "[.media-bench]") {
    const Scene scene = load_scene(SWEEPTRACE_SOURCE_DIR "/scenes/media/smoke.json");
    REQUIRE(scene.media.size() == 1);
    const int rays = 200000;
    const BenchRun grid = bench_run(MediumModel(scene.media[0], 16), rays);
    const BenchRun global = bench_run(MediumModel(scene.media[0], 1), rays);
    std::printf("scenes/media/smoke.json, %d rays through the smoke's box (CPU time)\n", rays);
    std::printf("                  collisions/ray (ratio, delta)   us/ray (ratio, delta)\n");
    for (const auto& [name, r] : {std::pair<const char*, const BenchRun&>{"16^3 majorants", grid}, {"one majorant  ", global}})
        std::printf("  %s   %8.2f %8.2f                    %6.3f %6.3f\n", name, double(r.ratio_collisions) / rays,
                    double(r.delta_collisions) / rays, 1e6 * r.ratio_seconds / rays, 1e6 * r.delta_seconds / rays);
    std::printf("  gain: %.2fx fewer ratio-tracking collisions, %.2fx fewer delta-tracking ones\n",
                double(global.ratio_collisions) / double(grid.ratio_collisions),
                double(global.delta_collisions) / double(grid.delta_collisions));
    CHECK(global.ratio_collisions >= 3 * grid.ratio_collisions);
}

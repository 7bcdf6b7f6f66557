// The render's memory estimate (cli/memory_budget.hpp) counts what each integrator and sampling
// mode keeps per pixel: a vcm light subpath per pixel, adaptive sampling's counts and round sums, the feature outputs' exact sums,
// so --max-memory refuses before the allocation rather than after it.
#include <catch2/catch.hpp>

#include <cstdint>

#include "raytracer/cli/memory_budget.hpp"
#include "raytracer/image/feature_sums.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/integrators/light_vertices.hpp"

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

// RenderOptions::time_budget: whole passes until the budget is spent, at least one, and the image
// is bit for bit the one of spp = completed_spp (budgets too small or too large to depend on the
// machine's speed, so the test never races the clock).
#include <catch2/catch.hpp>

#include <cstring>

#include "raytracer/render/renderer.hpp"
#include "render_test_scenes.hpp"

using namespace sweeptrace;
using sweeptrace::test::DoublePrecisionAccel;

namespace {

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

}  // namespace

TEST_CASE("render: a spent time budget keeps the first pass, a generous one stops at spp", "[render][time]") {
    const Scene s = test::two_light_scene(20, 20);
    const DoublePrecisionAccel accel(s);
    RenderOptions o;
    o.seed = 3;
    o.threads = 2;
    o.spp = 1;
    const RenderResult one = render(s, accel, o);
    for (const BudgetClock clock : {BudgetClock::Wall, BudgetClock::ProcessCpu}) {
        o.budget_clock = clock;
        o.spp = 1000;
        o.time_budget = 1e-9;  // spent before the first pass ends
        const RenderResult r = render(s, accel, o);
        CHECK(r.stats.budget_spent);
        CHECK_FALSE(r.stats.cancelled);
        CHECK(r.stats.completed_spp == 1);
        CHECK(same_bits(r.image, one.image));

        o.spp = 3;
        o.time_budget = 1e6;
        const RenderResult capped = render(s, accel, o);
        CHECK_FALSE(capped.stats.budget_spent);
        CHECK(capped.stats.completed_spp == 3);
    }
    o.time_budget = -1.0;
    CHECK_THROWS_AS(render(s, accel, o), std::invalid_argument);
}

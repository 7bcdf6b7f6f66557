// The thesis-faithful swept tests (collision::thesis::sweep) against the robust defaults: equal
// on generic input, apart exactly where the thesis's method breaks.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "collision/swept.hpp"
#include "collision/thesis/swept.hpp"
#include "random_cases.hpp"

using namespace collision;

TEST_CASE("thesis swept tests: where they break", "[thesis][swept]") {
    // A far, large configuration: the textbook quadratic loses the contact time.
    const Sphere far_still{{1e5f, 1e5f, 0}, 1.0f};
    const Sphere far_moving{{1e5f - 10.0f, 1e5f, 0}, 1.0f};
    const TimeOfImpact robust = sweep(far_moving, {20, 0, 0}, far_still);
    REQUIRE(robust.hit);
    CHECK(robust.t == Approx(0.4f).epsilon(1e-4));
    const TimeOfImpact textbook = thesis::sweep(far_moving, {20, 0, 0}, far_still);
    CHECK((!textbook.hit || std::abs(textbook.t - 0.4f) > 1e-3f));
    // A sphere starting on the far side of the grown sphere: no t = 0 answer, the exit instead.
    const TimeOfImpact inside = thesis::sweep(Sphere{{0.5f, 0, 0}, 1}, {1, 0, 0}, Sphere{{0, 0, 0}, 1});
    CHECK((!inside.hit || inside.t > 0.0f));
    CHECK(sweep(Sphere{{0.5f, 0, 0}, 1}, {1, 0, 0}, Sphere{{0, 0, 0}, 1}).t == 0.0f);
}

TEST_CASE("thesis swept tests agree with the defaults on generic random input", "[thesis][swept][random]") {
    testing::SeededRng rng(55);
    int compared = 0;
    for (int i = 0; i < 3000; ++i) {
        const Triangle tri = rng.triangle({0, 0, 0}, 1.5f);
        const Sphere m{rng.vec(-3, 3), rng.uniform(0.1f, 1.0f)};
        const glm::vec3 motion = -m.center * rng.uniform(0.2f, 1.6f) + rng.vec(-1, 1);
        const TimeOfImpact a = sweep(m, motion, tri);
        if (a.hit && a.t == 0.0f) continue;  // starts overlapping: the thesis has no answer for it
        const TimeOfImpact b = thesis::sweep(m, motion, tri);
        INFO("case " << i);
        CHECK(a.hit == b.hit);
        if (a.hit && b.hit) CHECK(std::abs(a.t - b.t) < 1e-4f);
        const Sphere s{rng.vec(-1, 1), rng.uniform(0.1f, 1.0f)};
        const TimeOfImpact c = sweep(m, motion, s), d = thesis::sweep(m, motion, s);
        if (!(c.hit && c.t == 0.0f)) {
            CHECK(c.hit == d.hit);
            if (c.hit && d.hit) CHECK(std::abs(c.t - d.t) < 1e-4f);
        }
        const Ellipsoid e{m.center, rng.vec(0.2f, 1.0f)};
        const TimeOfImpact f = sweep(e, motion, tri), g = thesis::sweep(e, motion, tri);
        if (!(f.hit && f.t == 0.0f)) {
            CHECK(f.hit == g.hit);
            if (f.hit && g.hit) CHECK(std::abs(f.t - g.t) < 1e-4f);
        }
        ++compared;
    }
    CHECK(compared > 2000);
}

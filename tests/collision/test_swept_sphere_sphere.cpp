// Sphere-sphere, swept (thesis 3.1.2): hit, miss, tangent, start inside, degenerate, and
// 10,000 random cases against the discrete test.
#include <catch2/catch.hpp>

#include <limits>
#include <tuple>

#include <glm/geometric.hpp>

#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "random_cases.hpp"
#include "swept_check.hpp"

using namespace collision;

TEST_CASE("swept sphere-sphere: hit, miss, tangent, overlap at start, degenerate", "[swept][sphere]") {
    const Sphere still{{0, 0, 0}, 1};
    TimeOfImpact r = sweep(Sphere{{-5, 0, 0}, 1}, {10, 0, 0}, still);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.3f));
    CHECK(r.normal.x == Approx(-1.0f));
    CHECK(r.point.x == Approx(-1.0f));
    CHECK_FALSE(sweep(Sphere{{-5, 0, 0}, 1}, {2, 0, 0}, still).hit);    // stops short
    CHECK_FALSE(sweep(Sphere{{-5, 2.1f, 0}, 1}, {10, 0, 0}, still).hit);  // passes above
    CHECK_FALSE(sweep(Sphere{{-5, 0, 0}, 1}, {-10, 0, 0}, still).hit);  // moves away
    r = sweep(Sphere{{-5, 2, 0}, 1}, {10, 0, 0}, still);  // exactly tangent: closed sets touch
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.5f));
    CHECK(r.normal.y == Approx(1.0f));
    r = sweep(Sphere{{-5, 0, 0}, 1}, {3, 0, 0}, still);  // reaches contact exactly at t = 1
    REQUIRE(r.hit);
    CHECK(r.t == 1.0f);
    r = sweep(Sphere{{0.5f, 0, 0}, 1}, {10, 0, 0}, still);  // overlapping at start, moving away
    REQUIRE(r.hit);
    CHECK(r.t == 0.0f);
    CHECK(r.normal.x == Approx(1.0f));
    r = sweep(Sphere{{0, 0, 0}, 1}, {0, 0, 0}, still);  // coincident, no motion: +Y
    REQUIRE(r.hit);
    CHECK(r.normal == glm::vec3(0, 1, 0));
    CHECK_FALSE(sweep(Sphere{{-5, 0, 0}, 0}, {10, 0, 0}, still).hit);
    CHECK_FALSE(sweep(Sphere{{-5, 0, 0}, 1}, {std::numeric_limits<float>::quiet_NaN(), 0, 0}, still).hit);
    CHECK_FALSE(sweep(Sphere{{-5, 0, 0}, 1}, {10, 0, 0}, Sphere{{0, 0, 0}, -1}).hit);
}

TEST_CASE("swept sphere-sphere agrees with the discrete test on 10,000 random cases", "[swept][sphere][random]") {
    // 12 bounds every coordinate: centres within 3 sqrt(3), motions within ~8.
    const auto stats = testing::random_sweeps(101, 10000, 12.0, [](testing::SeededRng& rng) {
        const Sphere m{rng.vec(-3, 3), rng.uniform(0.05f, 1.0f)};
        const Sphere s{rng.vec(-1, 1), rng.uniform(0.05f, 1.0f)};
        return std::tuple{m, (s.center - m.center) * rng.uniform(0.2f, 1.6f) + rng.vec(-1, 1), s};
    });
    CHECK(stats.hits > 3000);
    CHECK(stats.misses > 2000);
    CHECK(stats.at_start > 100);
}

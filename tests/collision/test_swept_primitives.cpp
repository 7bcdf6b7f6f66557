// Box-box, cylinder-cylinder and capsule-capsule, swept (thesis 3.1.4, 3.1.5): hit, miss,
// tangent, overlap at start, parallel motion, degenerate, and 10,000 random cases each against
// the discrete test.
#include <catch2/catch.hpp>

#include <limits>
#include <tuple>

#include <glm/geometric.hpp>

#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "float_specials.hpp"
#include "random_cases.hpp"
#include "swept_check.hpp"

using namespace collision;

namespace {

// Aimed roughly at each other so about half the cases hit.
template <class Shape>
std::tuple<Shape, glm::vec3, Shape> aimed(testing::SeededRng& rng, const Shape& m, const Shape& s) {
    return {m, (s.center - m.center) * rng.uniform(0.2f, 1.6f) + rng.vec(-1, 1), s};
}

void check_counts(const testing::SweptCheckStats& stats) {
    CHECK(stats.hits > 3000);
    CHECK(stats.misses > 1000);
    CHECK(stats.at_start > 100);
}
}  // namespace

TEST_CASE("swept box-box: faces, edges, tangent sliding, start overlap, degenerate", "[swept][box]") {
    const Aabb still{{0, 0, 0}, {2, 2, 2}};
    TimeOfImpact r = sweep(Aabb{{-5, 0.5f, 0}, {1, 1, 1}}, {10, 0, 0}, still);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.35f));
    CHECK(r.normal == glm::vec3(-1, 0, 0));
    CHECK(r.point.x == Approx(-1.0f));
    CHECK(r.point.y == Approx(0.5f));
    CHECK_FALSE(sweep(Aabb{{-5, 1.6f, 0}, {1, 1, 1}}, {10, 0, 0}, still).hit);  // passes above
    // Sliding exactly along the top face (touching the whole way): the closed sets touch.
    r = sweep(Aabb{{-5, 1.5f, 0}, {1, 1, 1}}, {10, 0, 0}, still);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.35f));
    r = sweep(Aabb{{0, 0, 0}, {1, 1, 1}}, {10, 0, 0}, still);  // inside at start
    REQUIRE(r.hit);
    CHECK(r.t == 0.0f);
    // Diagonal approach onto an edge of the grown box.
    r = sweep(Aabb{{-3, -3, 0}, {1, 1, 1}}, {3, 3, 0}, still);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.5f));
    CHECK_FALSE(sweep(Aabb{{-5, 0, 0}, {1, -1, 1}}, {10, 0, 0}, still).hit);
    CHECK_FALSE(sweep(Aabb{{-5, 0, 0}, {1, 1, 1}}, {k_nan, 0, 0}, still).hit);
}

TEST_CASE("swept cylinder-cylinder: side, cap, rim, parallel to the axis, start overlap", "[swept][cylinder]") {
    const Cylinder still{{0, 0, 0}, 1, 2};
    TimeOfImpact r = sweep(Cylinder{{-5, 0, 0}, 0.5f, 1}, {10, 0, 0}, still);  // side
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.35f));
    CHECK(r.normal.x == Approx(-1.0f));
    CHECK(r.point.x == Approx(-1.0f));
    r = sweep(Cylinder{{0.2f, 5, 0}, 0.5f, 1}, {0, -10, 0}, still);  // cap, moving along the axis
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.35f));
    CHECK(r.normal == glm::vec3(0, 1, 0));
    CHECK(r.point.y == Approx(1.0f));
    // Passing the grown cylinder's corner region in XZ: a box of the same size would be hit.
    // (The path x - z = 2.5 passes 1.77 from the axis, inside the grown square's corner.)
    CHECK((sweep(Aabb{{-1, 0, -3.5f}, {1, 1, 1}}, {6, 0, 6}, Aabb{{0, 0, 0}, {2, 2, 2}}).hit));
    CHECK_FALSE((sweep(Cylinder{{-1, 0, -3.5f}, 0.5f, 1}, {6, 0, 6}, still).hit));
    CHECK_FALSE((sweep(Cylinder{{-5, 0, 1.6f}, 0.5f, 1}, {10, 0, 0}, still).hit));
    r = sweep(Cylinder{{-5, 0, 1.5f}, 0.5f, 1}, {10, 0, 0}, still);  // tangent to the grown side
    CHECK(r.hit);
    r = sweep(Cylinder{{0, 1.4f, 0}, 0.5f, 1}, {0, 10, 0}, still);  // overlapping at start
    REQUIRE(r.hit);
    CHECK(r.t == 0.0f);
    CHECK(r.normal == glm::vec3(0, 1, 0));
    CHECK_FALSE(sweep(Cylinder{{-5, 0, 0}, 0, 1}, {10, 0, 0}, still).hit);
    CHECK_FALSE(sweep(Cylinder{{-5, 0, 0}, 1, 1}, {10, 0, 0}, Cylinder{{0, 0, 0}, 1, k_nan}).hit);
}

TEST_CASE("swept capsule-capsule: side, rounded ends, coaxial, start overlap, degenerate", "[swept][capsule]") {
    const Capsule still{{0, 0, 0}, 1, 2};
    TimeOfImpact r = sweep(Capsule{{-5, 0, 0}, 0.5f, 1}, {10, 0, 0}, still);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.35f));
    CHECK(r.normal.x == Approx(-1.0f));
    CHECK(r.point.x == Approx(-1.0f));
    // Coaxial approach from above: end spheres meet at y = 1 + 1 (still top) ...
    r = sweep(Capsule{{0, 6, 0}, 0.5f, 1}, {0, -6, 0}, still);
    REQUIRE(r.hit);
    // ... moving bottom at 6 - 0.5 - 0.5 = 5 reaches the still top 1 + 1 = 2 after 3 of 6.
    CHECK(r.t == Approx(0.5f));
    CHECK(r.normal.y == Approx(1.0f));
    CHECK(r.point.y == Approx(2.0f));
    // Passing over a rounded end diagonally: a cylinder of the same size would be hit.
    // (Grown capsule: core y in [-1.5, 1.5], radius 1.5; the path at y = 2.8, z = 1.2 passes
    // 1.77 from the core's top, but inside the grown capsule's bounding cylinder.)
    CHECK((sweep(Cylinder{{-5, 2.8f, 1.2f}, 0.5f, 4}, {10, 0, 0}, Cylinder{{0, 0, 0}, 1, 2}).hit));
    CHECK_FALSE((sweep(Capsule{{-5, 2.8f, 1.2f}, 0.5f, 1}, {10, 0, 0}, still).hit));
    r = sweep(Capsule{{-5, 0, 1.5f}, 0.5f, 1}, {10, 0, 0}, still);  // exactly tangent to the side
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.5f));
    r = sweep(Capsule{{0.5f, 0, 0}, 0.5f, 1}, {10, 0, 0}, still);  // overlapping at start
    REQUIRE(r.hit);
    CHECK(r.t == 0.0f);
    CHECK(r.normal.x == Approx(1.0f));
    CHECK_FALSE(sweep(Capsule{{-5, 0, 0}, -0.5f, 1}, {10, 0, 0}, still).hit);
    CHECK_FALSE(sweep(Capsule{{-5, 0, 0}, 0.5f, 1}, {10, k_nan, 0}, still).hit);
}

TEST_CASE("swept box-box agrees with the discrete test on 10,000 random cases", "[swept][box][random]") {
    // Scale 12 bounds every coordinate and size involved (here and below).
    check_counts(testing::random_sweeps(11, 10000, 12.0, [](testing::SeededRng& rng) {
        return aimed(rng, Aabb{rng.vec(-3, 3), rng.vec(0.1f, 2.0f)}, Aabb{rng.vec(-1, 1), rng.vec(0.1f, 2.0f)});
    }));
}

TEST_CASE("swept cylinder-cylinder agrees with the discrete test on 10,000 random cases", "[swept][cylinder][random]") {
    check_counts(testing::random_sweeps(12, 10000, 12.0, [](testing::SeededRng& rng) {
        return aimed(rng, Cylinder{rng.vec(-3, 3), rng.uniform(0.05f, 1), rng.uniform(0.05f, 2)},
                     Cylinder{rng.vec(-1, 1), rng.uniform(0.05f, 1), rng.uniform(0.05f, 2)});
    }));
}

TEST_CASE("swept capsule-capsule agrees with the discrete test on 10,000 random cases", "[swept][capsule][random]") {
    check_counts(testing::random_sweeps(13, 10000, 12.0, [](testing::SeededRng& rng) {
        return aimed(rng, Capsule{rng.vec(-3, 3), rng.uniform(0.05f, 1), rng.uniform(0, 2)},
                     Capsule{rng.vec(-1, 1), rng.uniform(0.05f, 1), rng.uniform(0, 2)});
    }));
}

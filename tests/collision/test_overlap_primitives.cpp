// Discrete sphere-sphere, box-box, cylinder-cylinder and capsule-capsule (thesis 3.1).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "collision/finite.hpp"
#include "collision/overlap.hpp"
#include "float_specials.hpp"
#include "random_cases.hpp"

using namespace collision;

namespace {
const float qinf = std::numeric_limits<float>::infinity();

// After moving the first shape by its displacement (plus a hair, 1e-4 relative, so rounding of
// the moved centre, a few float ulps, cannot leave it touching) the pair must no longer overlap, and
// moving it by slightly less (1 - 1e-4) must still overlap: the vector is a minimal one along
// its direction.
template <class A, class B>
void check_separates(A a, const B& b, const Contact& c) {
    REQUIRE(c.hit);
    REQUIRE(finite(c.displacement));
    const glm::vec3 start = a.center;
    // Below this the 1e-4 margin is within a few ulps of the centres and says nothing.
    const float scale = std::max({1.0f, std::abs(start.x), std::abs(start.y), std::abs(start.z)});
    if (1e-4f * glm::length(c.displacement) < 16.0f * std::numeric_limits<float>::epsilon() * scale) return;
    a.center = start + c.displacement * (1.0f + 1e-4f);
    CHECK_FALSE(overlap(a, b).hit);
    a.center = start + c.displacement * (1.0f - 1e-4f);
    CHECK(overlap(a, b).hit);
}
}  // namespace

TEST_CASE("sphere-sphere: hit, miss, tangent, inside, coincident, degenerate", "[overlap][sphere]") {
    Sphere a{{0, 0, 0}, 1}, b{{1.5f, 0, 0}, 1};
    Contact c = overlap(a, b);
    REQUIRE(c.hit);
    CHECK(c.displacement.x == Approx(-0.5f));
    CHECK(c.displacement.y == 0.0f);
    check_separates(a, b, c);

    CHECK_FALSE((overlap(Sphere{{0, 0, 0}, 1}, Sphere{{2.5f, 0, 0}, 1}).hit));  // miss
    c = overlap(Sphere{{0, 0, 0}, 1}, Sphere{{2, 0, 0}, 1});                  // tangent: touching counts
    CHECK(c.hit);
    CHECK(glm::length(c.displacement) == 0.0f);
    c = overlap(Sphere{{0.1f, 0, 0}, 0.2f}, Sphere{{0, 0, 0}, 5});  // small one inside the big one
    REQUIRE(c.hit);
    CHECK(c.displacement.x == Approx(5.1f));
    // Coincident centres: the thesis normalises a zero vector (NaN); we push along +Y.
    c = overlap(Sphere{{3, 3, 3}, 1}, Sphere{{3, 3, 3}, 2});
    REQUIRE(c.hit);
    CHECK(c.displacement == glm::vec3(0, 3, 0));
    // Degenerate.
    CHECK_FALSE((overlap(Sphere{{0, 0, 0}, 0}, Sphere{{0, 0, 0}, 1}).hit));
    CHECK_FALSE((overlap(Sphere{{0, 0, 0}, -1}, Sphere{{0, 0, 0}, 1}).hit));
    CHECK_FALSE((overlap(Sphere{{k_nan, 0, 0}, 1}, Sphere{{0, 0, 0}, 1}).hit));
    CHECK_FALSE((overlap(Sphere{{0, 0, 0}, k_nan}, Sphere{{0, 0, 0}, 1}).hit));
    CHECK_FALSE((overlap(Sphere{{qinf, 0, 0}, 1}, Sphere{{qinf, 0, 0}, 1}).hit));
}

TEST_CASE("box-box: least-overlap axis, sign, tangent, inside, degenerate", "[overlap][box]") {
    Aabb a{{0, 0, 0}, {2, 2, 2}}, b{{1.5f, 0.2f, -0.1f}, {2, 2, 2}};
    Contact c = overlap(a, b);
    REQUIRE(c.hit);
    CHECK(c.displacement == glm::vec3(-0.5f, 0, 0));
    check_separates(a, b, c);
    CHECK_FALSE((overlap(a, Aabb{{0, 2.01f, 0}, {2, 2, 2}}).hit));
    CHECK((overlap(a, Aabb{{0, 2, 0}, {2, 2, 2}}).hit));  // face contact counts
    c = overlap(Aabb{{0, 0.25f, 0}, {1, 1, 1}}, Aabb{{0, 0, 0}, {10, 10, 10}});  // inside
    REQUIRE(c.hit);
    CHECK(c.displacement == glm::vec3(0, 5.5f - 0.25f, 0));  // x and z need 5.5, y less
    // Equal centres: ties go to x, then the push is toward +x.
    c = overlap(Aabb{{1, 1, 1}, {2, 2, 2}}, Aabb{{1, 1, 1}, {2, 2, 2}});
    CHECK(c.displacement == glm::vec3(2, 0, 0));
    // A flat box (zero size on y) is a valid closed set.
    CHECK((overlap(Aabb{{0, 0, 0}, {1, 0, 1}}, Aabb{{0, 0.5f, 0}, {1, 1, 1}}).hit));
    CHECK_FALSE((overlap(Aabb{{0, 0, 0}, {1, -1, 1}}, a).hit));
    CHECK_FALSE((overlap(Aabb{{0, k_nan, 0}, {1, 1, 1}}, a).hit));
    CHECK_FALSE((overlap(Aabb{{0, 0, 0}, {1, qinf, 1}}, a).hit));
}

TEST_CASE("cylinder-cylinder: cap vs side resolution, coaxial, tangent, degenerate", "[overlap][cylinder]") {
    // Side contact is shallower.
    Cylinder a{{0, 0, 0}, 1, 4}, b{{1.8f, 0.5f, 0}, 1, 4};
    Contact c = overlap(a, b);
    REQUIRE(c.hit);
    CHECK(c.displacement.x == Approx(-0.2f));
    CHECK(c.displacement.y == 0.0f);
    check_separates(a, b, c);
    // Cap contact is shallower.
    Cylinder d{{0.3f, 3.9f, 0}, 1, 4};
    c = overlap(d, a);
    REQUIRE(c.hit);
    CHECK(c.displacement.x == 0.0f);
    CHECK(c.displacement.y == Approx(0.1f).epsilon(1e-5));
    CHECK(c.displacement.z == 0.0f);
    check_separates(d, a, c);
    // Within height range but circles apart: miss; corner-to-corner near miss (box would hit).
    CHECK_FALSE((overlap(a, Cylinder{{2.1f, 0, 0}, 1, 4}).hit));
    CHECK_FALSE((overlap(a, Cylinder{{1.5f, 0, 1.5f}, 1, 4}).hit));
    CHECK((overlap(a, Cylinder{{2, 0, 0}, 1, 4}).hit));  // tangent sides
    CHECK((overlap(a, Cylinder{{0, 4, 0}, 1, 4}).hit));  // caps touching
    // Coaxial: horizontal direction undefined, pushed along +X unless the cap is shallower.
    c = overlap(Cylinder{{0, 0, 0}, 1, 10}, Cylinder{{0, 0, 0}, 0.5f, 10});
    CHECK(c.displacement == glm::vec3(1.5f, 0, 0));
    CHECK((overlap(Cylinder{{0, 0, 0}, 1, 0}, a).hit));  // a disk is fine
    CHECK_FALSE((overlap(Cylinder{{0, 0, 0}, 0, 1}, a).hit));
    CHECK_FALSE((overlap(Cylinder{{0, 0, 0}, 1, -1}, a).hit));
    CHECK_FALSE((overlap(Cylinder{{0, 0, 0}, 1, k_nan}, a).hit));
}

TEST_CASE("capsule-capsule: side, hemisphere, coaxial, tangent, degenerate", "[overlap][capsule]") {
    Capsule a{{0, 0, 0}, 1, 2};
    Contact c = overlap(a, Capsule{{1.5f, 0.5f, 0}, 1, 2});  // side by side
    REQUIRE(c.hit);
    CHECK(c.displacement.x == Approx(-0.5f));
    check_separates(a, Capsule{{1.5f, 0.5f, 0}, 1, 2}, c);
    // End to end, offset sideways: hemisphere contact along the diagonal.
    const Capsule top{{1, 3.5f, 0}, 1, 2};
    c = overlap(top, a);
    REQUIRE(c.hit);
    const float gap = std::sqrt(1.0f + 1.5f * 1.5f);
    CHECK(glm::length(c.displacement) == Approx(2.0f - gap));
    CHECK(c.displacement.x > 0.0f);
    CHECK(c.displacement.y > 0.0f);
    check_separates(top, a, c);
    // A box-like test would hit here; the rounded ends miss.
    CHECK_FALSE((overlap(a, Capsule{{1.9f, 3.9f, 0}, 1, 2}).hit));
    CHECK((overlap(a, Capsule{{0, 4, 0}, 1, 2}).hit));  // tangent end caps
    c = overlap(Capsule{{0, 0.5f, 0}, 1, 2}, Capsule{{0, 0, 0}, 2, 2});  // coaxial
    CHECK(c.displacement == glm::vec3(3, 0, 0));
    CHECK((overlap(Capsule{{0, 0, 0}, 1, 0}, a).hit));  // height 0 is a sphere
    CHECK_FALSE((overlap(Capsule{{0, 0, 0}, -1, 1}, a).hit));
    CHECK_FALSE((overlap(Capsule{{k_nan, 0, 0}, 1, 1}, a).hit));
}

TEST_CASE("primitive pairs: the displacement separates and is minimal along itself (random)", "[overlap][random]") {
    testing::SeededRng rng(1234);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 p = rng.vec(-2, 2), q = rng.vec(-2, 2);
        const float r1 = rng.uniform(0.1f, 1.5f), r2 = rng.uniform(0.1f, 1.5f);
        const float h1 = rng.uniform(0.0f, 2.0f), h2 = rng.uniform(0.0f, 2.0f);
        const Sphere s1{p, r1}, s2{q, r2};
        if (Contact c = overlap(s1, s2); c.hit) check_separates(s1, s2, c), ++hits;
        const Aabb b1{p, rng.vec(0.1f, 2.5f)}, b2{q, rng.vec(0.1f, 2.5f)};
        if (Contact c = overlap(b1, b2); c.hit) check_separates(b1, b2, c), ++hits;
        const Cylinder c1{p, r1, h1}, c2{q, r2, h2};
        if (Contact c = overlap(c1, c2); c.hit) check_separates(c1, c2, c), ++hits;
        const Capsule k1{p, r1, h1}, k2{q, r2, h2};
        if (Contact c = overlap(k1, k2); c.hit) check_separates(k1, k2, c), ++hits;
    }
    CHECK(hits > 2000);  // the cases exercise overlap, not only misses
}

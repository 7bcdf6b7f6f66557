// The thesis-faithful discrete tests (collision::thesis): they agree with the robust defaults
// on generic input and fail exactly where the thesis's method does.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "collision/overlap.hpp"
#include "collision/thesis/overlap.hpp"
#include "random_cases.hpp"
#include "tri_tri_reference.hpp"

using namespace collision;

namespace {
bool has_nan(const glm::vec3& v) { return std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z); }
}  // namespace

TEST_CASE("thesis discrete tests: where they break", "[thesis][overlap]") {
    // Coincident centres / coaxial cylinders: normalize of a zero vector.
    CHECK(has_nan(thesis::overlap(Sphere{{1, 1, 1}, 1}, Sphere{{1, 1, 1}, 1}).displacement));
    CHECK_FALSE(has_nan(overlap(Sphere{{1, 1, 1}, 1}, Sphere{{1, 1, 1}, 1}).displacement));
    CHECK(has_nan(thesis::overlap(Cylinder{{0, 0, 0}, 1, 10}, Cylinder{{0, 0.1f, 0}, 1, 10}).displacement));
    // Touching cylinders: strict comparison says apart.
    CHECK_FALSE(thesis::overlap(Cylinder{{0, 0, 0}, 1, 2}, Cylinder{{2, 0, 0}, 1, 2}).hit);
    CHECK(overlap(Cylinder{{0, 0, 0}, 1, 2}, Cylinder{{2, 0, 0}, 1, 2}).hit);
    // Coplanar triangles, clearly overlapping: the thesis says apart.
    const Triangle t{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, u{{0.5f, 0.5f, 0}, {3, 0.5f, 0}, {0.5f, 3, 0}};
    CHECK_FALSE(thesis::overlap(t, u));
    CHECK(overlap(t, u));
    // Capsules side by side with a short vertical overlap: the thesis's cylinder test resolves
    // along Y by the cap depth 0.1 -- there are no caps, and that does not separate them.
    const Capsule a{{0, 0, 0}, 0.5f, 2}, b{{0.5f, 1.9f, 0}, 0.5f, 2};
    const Contact c = thesis::overlap(a, b);
    REQUIRE(c.hit);
    Capsule moved = a;
    moved.center += c.displacement * 1.01f;
    CHECK(overlap(moved, b).hit);  // still overlapping after the thesis's "resolution"
    const Contact good = overlap(a, b);
    moved.center = a.center + good.displacement * 1.01f;
    CHECK_FALSE(overlap(moved, b).hit);
}

TEST_CASE("thesis discrete tests agree with the defaults on generic random input", "[thesis][overlap][random]") {
    testing::SeededRng rng(8);
    int agree_tt = 0, cases_tt = 0;
    for (int i = 0; i < 5000; ++i) {
        const Sphere s1{rng.vec(-2, 2), rng.uniform(0.1f, 1.5f)}, s2{rng.vec(-2, 2), rng.uniform(0.1f, 1.5f)};
        const Contact a = thesis::overlap(s1, s2), b = overlap(s1, s2);
        CHECK(a.hit == b.hit);
        if (a.hit) CHECK(glm::length(a.displacement - b.displacement) < 1e-4f);
        const Capsule k1{s1.center, s1.radius, rng.uniform(0, 2)}, k2{s2.center, s2.radius, rng.uniform(0, 2)};
        CHECK(thesis::overlap(k1, k2).hit == overlap(k1, k2).hit);  // detection is exact in both
        const Triangle tri = rng.triangle({0, 0, 0}, 1.5f);
        const Contact st = thesis::overlap(s1, tri), sd = overlap(s1, tri);
        CHECK(st.hit == sd.hit);
        const Triangle p = rng.triangle({0, 0, 0}, 1), q = rng.triangle(rng.vec(-0.8f, 0.8f), 1);
        if (std::abs(testing::tri_tri_gap(p, q)) > 1e-4L) {
            ++cases_tt;
            agree_tt += thesis::overlap(p, q) == overlap(p, q);
        }
    }
    CHECK(agree_tt == cases_tt);  // non-coplanar, not touching: Möller is Möller
}

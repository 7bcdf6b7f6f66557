// Closest point on a triangle, sphere-triangle and ellipsoid-triangle, discrete (thesis 3.2.4,
// 3.2.6).
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
using lvec = glm::tvec3<long double>;

lvec L(const glm::vec3& v) { return lvec(v); }

// Independent reference in long double: project on the plane, keep the projection when its
// barycentrics are inside, otherwise the nearest of the three edge segments.
lvec reference_closest(const Triangle& t, const glm::vec3& pf) {
    const lvec a = L(t.a), b = L(t.b), c = L(t.c), p = L(pf);
    const lvec n = glm::cross(b - a, c - a);
    const lvec q = p - n * (glm::dot(p - a, n) / glm::dot(n, n));
    const long double area = glm::dot(n, n);
    const long double u = glm::dot(glm::cross(b - q, c - q), n) / area;
    const long double v = glm::dot(glm::cross(c - q, a - q), n) / area;
    const long double w = 1.0L - u - v;
    if (u >= 0 && v >= 0 && w >= 0) return q;
    auto seg = [&](const lvec& s0, const lvec& s1) {
        long double s = glm::dot(p - s0, s1 - s0) / glm::dot(s1 - s0, s1 - s0);
        s = std::clamp(s, 0.0L, 1.0L);
        return s0 + (s1 - s0) * s;
    };
    lvec best = seg(a, b);
    for (const lvec& e : {seg(b, c), seg(c, a)})
        if (glm::length(e - p) < glm::length(best - p)) best = e;
    return best;
}

}  // namespace

TEST_CASE("closest point on triangle: every Voronoi region, and a long double reference", "[overlap][closest]") {
    const Triangle t{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    CHECK((closest_point(t, {0.5f, 0.5f, 3}) == glm::vec3(0.5f, 0.5f, 0)));  // face
    CHECK((closest_point(t, {-1, -1, 1}) == glm::vec3(0, 0, 0)));            // vertex a
    CHECK((closest_point(t, {3, -1, 0}) == glm::vec3(2, 0, 0)));             // vertex b
    CHECK((closest_point(t, {-1, 3, 0}) == glm::vec3(0, 2, 0)));             // vertex c
    CHECK((closest_point(t, {1, -1, 0}) == glm::vec3(1, 0, 0)));             // edge ab
    CHECK((closest_point(t, {-1, 1, 0}) == glm::vec3(0, 1, 0)));             // edge ac
    CHECK((closest_point(t, {2, 2, 0}) == glm::vec3(1, 1, 0)));              // edge bc
    // Degenerate (collinear) triangle: still a point of the segment, never NaN.
    const glm::vec3 q = closest_point(Triangle{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {1.5f, 1, 0});
    CHECK(q == glm::vec3(1.5f, 0, 0));
    CHECK((finite(closest_point(Triangle{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, {0, 0, 0}))));

    // Random: error bound 0.5 ulp of float per component after rounding the double result, plus
    // double error ~1e-15 relative; we check |q - ref| <= 2 ulp(max(|p|, |vertices|)).
    testing::SeededRng rng(77);
    for (int i = 0; i < 20000; ++i) {
        const Triangle tri = rng.triangle(rng.vec(-10, 10), 5);
        const glm::vec3 p = rng.vec(-15, 15);
        const lvec ref = reference_closest(tri, p);
        const glm::vec3 got = closest_point(tri, p);
        const float scale = std::max({glm::length(p), glm::length(tri.a), glm::length(tri.b), glm::length(tri.c)});
        const long double err = glm::length(L(got) - ref);
        INFO("case " << i);
        REQUIRE(err <= 4.0L * std::numeric_limits<float>::epsilon() * scale);
    }
}

TEST_CASE("sphere-triangle: face, edge, vertex, tangent, centre on triangle, degenerate", "[overlap][sphere_triangle]") {
    const Triangle t{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    Contact c = overlap(Sphere{{0.5f, 0.5f, 0.8f}, 1}, t);  // face
    REQUIRE(c.hit);
    CHECK(c.displacement.z == Approx(0.2f));
    CHECK(c.displacement.x == 0.0f);
    c = overlap(Sphere{{1, -0.5f, 0}, 1}, t);  // edge ab, in plane
    REQUIRE(c.hit);
    CHECK(c.displacement.y == Approx(-0.5f));
    c = overlap(Sphere{{-0.6f, -0.6f, 0.3f}, 1}, t);  // vertex a
    REQUIRE(c.hit);
    CHECK(glm::length(c.displacement) == Approx(1.0f - std::sqrt(0.36f + 0.36f + 0.09f)));
    CHECK_FALSE((overlap(Sphere{{0.5f, 0.5f, 1.1f}, 1}, t).hit));  // above
    CHECK_FALSE((overlap(Sphere{{2, 2, 0}, 1}, t).hit));           // beyond edge bc: distance sqrt(2)
    CHECK((overlap(Sphere{{0.5f, 0.5f, 1}, 1}, t).hit));           // tangent
    c = overlap(Sphere{{0.5f, 0.5f, 0}, 0.25f}, t);              // centre on the triangle
    CHECK(c.displacement == glm::vec3(0, 0, 0.25f));             // along the front normal
    c = overlap(Sphere{{0.5f, 0.5f, 0}, 0.25f}, Triangle{t.a, t.c, t.b});
    CHECK(c.displacement == glm::vec3(0, 0, -0.25f));
    CHECK_FALSE((overlap(Sphere{{0, 0, 0}, 1}, Triangle{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).hit));  // zero area
    CHECK_FALSE((overlap(Sphere{{0, 0, 0}, 0}, t).hit));
    CHECK_FALSE((overlap(Sphere{{0, 0, 0}, 1}, Triangle{{k_nan, 0, 0}, {1, 0, 0}, {0, 1, 0}}).hit));
}

TEST_CASE("sphere-triangle: displacement is exact against the long double reference (random)", "[overlap][sphere_triangle]") {
    testing::SeededRng rng(5);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Triangle tri = rng.triangle({0, 0, 0}, 2);
        const Sphere s{rng.vec(-3, 3), rng.uniform(0.1f, 2.0f)};
        const lvec ref = reference_closest(tri, s.center);
        const long double dist = glm::length(L(s.center) - ref);
        const Contact c = overlap(s, tri);
        INFO("case " << i);
        // Decision: exact unless the sphere is within ~1e-6 of touching.
        if (std::abs(dist - s.radius) > 1e-5L) REQUIRE(c.hit == (dist < s.radius));
        if (c.hit && dist > 1e-3L) {
            ++hits;
            const lvec want = (L(s.center) - ref) * ((s.radius - dist) / dist);
            REQUIRE(glm::length(L(c.displacement) - want) <= 1e-5L);
        }
    }
    CHECK(hits > 2000);
}

TEST_CASE("ellipsoid-triangle: overlap is exact, the vector separates within the stated bound", "[overlap][ellipsoid]") {
    const Triangle t{{-5, 0, -5}, {5, 0, -5}, {0, 0, 5}};  // the y = 0 plane, facing -y
    Contact c = overlap(Ellipsoid{{0, 1.5f, 0}, {1, 2, 1}}, t);
    REQUIRE(c.hit);
    // Scaled space: centre at y = 0.75, depth 0.25, back to y: 0.5 (exact for a face contact).
    CHECK(glm::length(c.displacement) == Approx(0.5f));
    CHECK_FALSE((overlap(Ellipsoid{{0, 2.1f, 0}, {1, 2, 1}}, t).hit));
    CHECK((overlap(Ellipsoid{{0, 2, 0}, {1, 2, 1}}, t).hit));  // tangent
    CHECK_FALSE((overlap(Ellipsoid{{0, 0, 0}, {1, 0, 1}}, t).hit));
    CHECK_FALSE((overlap(Ellipsoid{{0, 0, 0}, {1, k_nan, 1}}, t).hit));

    // Random: the answer matches a direct test (closest point inside the ellipsoid's implicit
    // function, long double), and moving by the vector separates. The minimal translation d*
    // is the minimum over unit u of h_T(u) + h_E(-u) (support functions); sampling u gives an
    // upper bound U >= |d*|, and the stated bound says |vector| <= (rmax / rmin) |d*|.
    testing::SeededRng rng(9);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const Triangle tri = rng.triangle({0, 0, 0}, 2);
        const Ellipsoid e{rng.vec(-2, 2), rng.vec(0.2f, 1.5f)};
        const Contact k = overlap(e, tri);
        const Triangle scaled{(tri.a - e.center) / e.radii, (tri.b - e.center) / e.radii, (tri.c - e.center) / e.radii};
        const lvec ref = reference_closest(scaled, {0, 0, 0});
        const long double dist = glm::length(ref);
        INFO("case " << i);
        if (std::abs(dist - 1.0L) > 1e-5L) REQUIRE(k.hit == (dist < 1.0L));
        if (!k.hit || dist > 0.999L) continue;
        ++hits;
        Ellipsoid moved = e;
        moved.center += k.displacement * 1.001f;
        CHECK_FALSE(overlap(moved, tri).hit);
        long double upper = std::numeric_limits<long double>::infinity();
        for (int s = 0; s < 400; ++s) {
            const glm::vec3 u = glm::normalize(rng.vec(-1, 1) + glm::vec3(1e-6f));
            const long double ht = std::max({glm::dot(L(tri.a), L(u)), glm::dot(L(tri.b), L(u)), glm::dot(L(tri.c), L(u))});
            const long double he = -glm::dot(L(e.center), L(u)) + glm::length(L(e.radii) * L(u));
            upper = std::min(upper, ht + he);
        }
        const float ratio = std::max({e.radii.x, e.radii.y, e.radii.z}) / std::min({e.radii.x, e.radii.y, e.radii.z});
        CHECK(glm::length(k.displacement) <= ratio * upper * 1.0001L);
    }
    CHECK(hits > 300);
}

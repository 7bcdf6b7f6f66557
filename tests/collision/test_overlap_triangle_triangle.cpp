// Triangle-triangle (Möller 1997 with the coplanar case) and plane-plane (thesis 3.2.2, 3.2.3).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "collision/overlap.hpp"
#include "float_specials.hpp"
#include "random_cases.hpp"
#include "tri_tri_reference.hpp"

using namespace collision;

namespace {
bool both_ways(const Triangle& a, const Triangle& b) {
    const bool ab = overlap(a, b), ba = overlap(b, a);
    CHECK(ab == ba);
    return ab;
}
}  // namespace

TEST_CASE("triangle-triangle: crossing, apart, touching, vertex on face, degenerate", "[overlap][tri_tri]") {
    const Triangle t{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    CHECK((both_ways(t, Triangle{{0.5f, 0.5f, -1}, {0.5f, 0.5f, 1}, {3, 3, 0.5f}})));         // pierces
    CHECK_FALSE((both_ways(t, Triangle{{0.5f, 0.5f, 0.1f}, {1, 0.5f, 1}, {0.5f, 1, 1}})));     // above
    CHECK_FALSE((both_ways(t, Triangle{{3, 3, -1}, {3, 3, 1}, {4, 2, 0}})));                   // planes cross, beside
    CHECK((both_ways(t, Triangle{{0.5f, 0.5f, 0}, {1, 0.5f, 1}, {0.5f, 1, 1}})));              // vertex on face
    CHECK((both_ways(t, Triangle{{1, 1, -1}, {1, 1, 1}, {3, 3, 0}})));                         // edge through edge bc
    CHECK((both_ways(t, Triangle{{2, 0, 0}, {3, 0, 1}, {3, 1, 0}})));                          // shared vertex only
    CHECK_FALSE((both_ways(t, Triangle{{2.001f, 0, 0}, {3, 0, 1}, {3, 1, 0}})));
    // Parallel planes, apart.
    CHECK_FALSE((both_ways(t, Triangle{{0, 0, 1}, {2, 0, 1}, {0, 2, 1}})));
    // Degenerate: zero area, NaN.
    CHECK_FALSE((both_ways(t, Triangle{{0, 0, -1}, {0, 0, 0}, {0, 0, 1}})));
    CHECK_FALSE((both_ways(t, Triangle{{k_nan, 0, 0}, {1, 0, 0}, {0, 1, 1}})));
}

TEST_CASE("triangle-triangle: the coplanar case the thesis skips", "[overlap][tri_tri][coplanar]") {
    const Triangle t{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    CHECK((both_ways(t, Triangle{{1, 1, 0}, {3, 1, 0}, {1, 3, 0}})));                 // edges cross
    CHECK((both_ways(t, Triangle{{0.2f, 0.2f, 0}, {0.5f, 0.2f, 0}, {0.2f, 0.5f, 0}}))); // B inside A
    CHECK((both_ways(Triangle{{0.2f, 0.2f, 0}, {0.5f, 0.2f, 0}, {0.2f, 0.5f, 0}}, t))); // A inside B
    CHECK((both_ways(t, Triangle{{-1, -1, 0}, {5, -1, 0}, {-1, 5, 0}})));             // A inside B (large)
    CHECK_FALSE((both_ways(t, Triangle{{1.1f, 1.1f, 0}, {3, 1.1f, 0}, {1.1f, 3, 0}}))); // beside bc
    CHECK((both_ways(t, Triangle{{1, 1, 0}, {3, 1, 0}, {1, 3, 0}})));                 // vertex on edge
    CHECK((both_ways(t, Triangle{{2, 0, 0}, {4, 0, 0}, {3, 1, 0}})));                 // shared vertex
    CHECK((both_ways(t, Triangle{{1, 0, 0}, {3, 0, 0}, {2, -1, 0}})));                // collinear edge overlap
    CHECK(both_ways(t, t));                                                          // identical
    CHECK_FALSE((both_ways(t, Triangle{{0, -0.1f, 0}, {2, -0.1f, 0}, {1, -1, 0}})));  // parallel edge, apart
    // Tilted plane (dominant normal axis not z).
    const Triangle u{{0, 0, 0}, {0, 2, 0.1f}, {0, 0.1f, 2}};
    CHECK((both_ways(u, Triangle{{0, 0.5f, 0.5f}, {0, 3, 0.65f}, {0, 0.6f, 3}})));
}

TEST_CASE("triangle-triangle agrees with a long double separating-axis reference (random)", "[overlap][tri_tri][random]") {
    testing::SeededRng rng(2024);
    int hits = 0, coplanar = 0;
    for (int i = 0; i < 40000; ++i) {
        Triangle a = rng.triangle({0, 0, 0}, 1), b = rng.triangle(rng.vec(-0.8f, 0.8f), 1);
        if (i % 4 == 0) {  // coplanar: both in z = 0 (exactly representable)
            a.a.z = a.b.z = a.c.z = b.a.z = b.b.z = b.c.z = 0.0f;
            ++coplanar;
        }
        const long double gap = testing::tri_tri_gap(a, b);
        if (std::abs(gap) < 1e-6L) continue;  // too close to touching for the float inputs to decide
        INFO("case " << i << " gap " << double(gap));
        const bool got = overlap(a, b);
        REQUIRE(got == (gap < 0));
        REQUIRE(overlap(b, a) == got);
        hits += got;
    }
    CHECK(hits > 3000);
    CHECK(coplanar == 10000);
}

TEST_CASE("plane-plane: the intersection line, parallel planes, degenerate", "[overlap][plane]") {
    const auto line = intersect(Plane{{0, 1, 0}, {0, 1, 0}}, Plane{{2, 0, 0}, {1, 0, 0}});
    REQUIRE(line);
    CHECK(line->point == glm::vec3(2, 1, 0));  // the thesis's formula as printed gives (-2, -1, 0)
    CHECK(std::abs(line->direction.z) == 1.0f);
    CHECK_FALSE((intersect(Plane{{0, 1, 0}, {0, 1, 0}}, Plane{{0, 5, 0}, {0, -1, 0}})));
    CHECK_FALSE((intersect(Plane{{0, 1, 0}, {0, 1, 0}}, Plane{{0, 1, 0}, {0, 1, 0}})));
    CHECK_FALSE((intersect(Plane{{0, 1, 0}, {0, 0, 0}}, Plane{{0, 1, 0}, {1, 0, 0}})));
    CHECK_FALSE((intersect(Plane{{0, k_nan, 0}, {0, 1, 0}}, Plane{{0, 1, 0}, {1, 0, 0}})));

    // Random: the point lies on both planes and the direction in both, to the error the
    // geometry allows (float rounding of inputs/outputs amplified by 1 / sin(angle)).
    testing::SeededRng rng(31);
    for (int i = 0; i < 10000; ++i) {
        const Plane p{rng.vec(-10, 10), glm::normalize(rng.vec(-1, 1) + glm::vec3(1e-3f))};
        const Plane q{rng.vec(-10, 10), glm::normalize(rng.vec(-1, 1) + glm::vec3(1e-3f))};
        const auto l = intersect(p, q);
        const float s = glm::length(glm::cross(p.normal, q.normal));
        if (s < 1e-3f) continue;
        REQUIRE(l);
        const float scale = 40.0f / s;  // |point| is at most about 20 / sin(angle)
        const float tol = 8.0f * std::numeric_limits<float>::epsilon() * scale;
        CHECK(std::abs(glm::dot(l->point - p.point, p.normal)) <= tol);
        CHECK(std::abs(glm::dot(l->point - q.point, q.normal)) <= tol);
        CHECK(std::abs(glm::dot(l->direction, p.normal)) <= 1e-6f);
        CHECK(std::abs(glm::dot(l->direction, q.normal)) <= 1e-6f);
    }
}

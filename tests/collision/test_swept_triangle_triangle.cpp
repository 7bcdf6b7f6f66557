// Translational triangle-triangle, swept (thesis 3.5.2): vertex-face, face-vertex, edge-edge,
// in-plane motion, parallel edges, overlap at start, and 12,000 random cases against the
// discrete Möller test.
#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>
#include <limits>

#include <glm/geometric.hpp>

#include "collision/overlap.hpp"
#include "collision/intersect.hpp"
#include "collision/swept.hpp"
#include "random_cases.hpp"
#include "swept_check.hpp"

using namespace collision;

namespace {
const Triangle floor_tri{{-2, 0, -2}, {0, 0, 3}, {2, 0, -2}};
}  // namespace

TEST_CASE("swept triangle-triangle: vertex-face, face-vertex and edge-edge contacts", "[swept][tri_tri]") {
    // A vertex comes down onto the floor's face.
    const Triangle spike{{0, 1, 0}, {-1, 2, 0}, {1, 2, 0.5f}};
    TimeOfImpact r = sweep(spike, {0, -2, 0}, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.5f));
    CHECK(r.point.x == Approx(0.0f).margin(1e-6));
    CHECK(r.normal.y == Approx(1.0f));
    // The still triangle's vertex is hit by the moving face (roles swapped).
    const Triangle roof{{-3, 2, -3}, {3, 2, -3}, {0, 2, 4}};
    const Triangle tip{{0, 1, 0}, {-1, 0, 0}, {1, 0, 0.5f}};
    r = sweep(roof, {0, -2, 0}, tip);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.5f));
    CHECK(r.point == glm::vec3(0, 1, 0));
    CHECK(r.normal.y == Approx(1.0f));
    // Edge-edge: two crossed horizontal edges (no vertex ever touches a face first).
    const Triangle upper{{-1, 1, 0}, {1, 1, 0}, {0, 3, 0}};   // lowest edge along x at y = 1
    const Triangle lower{{0, 0, -1}, {0, 0, 1}, {0, -2, 0}};  // highest edge along z at y = 0
    r = sweep(upper, {0, -3, 0}, lower);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(1.0f / 3.0f));
    CHECK(glm::length(r.point - glm::vec3(0, 0, 0)) < 1e-6f);
    CHECK(r.normal.y == Approx(1.0f));
    // The thesis's first attempt (vertex paths only) misses this: every vertex path misses.
    for (const glm::vec3& v : {upper.a, upper.b, upper.c}) {
        RayHit h;
        CHECK_FALSE((intersect(Ray{v, {0, -3, 0}, 0, 1}, lower, h)));
    }
}

TEST_CASE("swept triangle-triangle: miss, t = 1 exactly, overlap at start, degenerate", "[swept][tri_tri]") {
    const Triangle spike{{0, 1, 0}, {-1, 2, 0}, {1, 2, 0.5f}};
    CHECK_FALSE(sweep(spike, {0, -0.9f, 0}, floor_tri).hit);  // stops short
    CHECK_FALSE(sweep(spike, {5, 0, 0}, floor_tri).hit);      // moves past, parallel to the floor
    TimeOfImpact r = sweep(spike, {0, -1, 0}, floor_tri);     // just reaches it at t = 1
    REQUIRE(r.hit);
    CHECK(r.t == 1.0f);
    r = sweep(Triangle{{0, -1, 0}, {-1, 1, 0}, {1, 1, 0}}, {0, 5, 0}, floor_tri);  // pierces at start
    REQUIRE(r.hit);
    CHECK(r.t == 0.0f);
    CHECK(std::abs(r.normal.y) == Approx(1.0f));
    r = sweep(Triangle{{0, -1, 0}, {-1, 1, 0}, {1, 1, 0}}, {0, 0, 0}, floor_tri);  // no motion
    CHECK(r.hit);
    CHECK_FALSE(sweep(spike, {0, 0, 0}, floor_tri).hit);
    // Degenerate triangles and non-finite input.
    CHECK_FALSE(sweep(Triangle{{0, 1, 0}, {0, 1, 0}, {1, 1, 0}}, {0, -5, 0}, floor_tri).hit);
    CHECK_FALSE(sweep(spike, {0, -std::numeric_limits<float>::infinity(), 0}, floor_tri).hit);
    CHECK_FALSE(sweep(spike, {0, std::numeric_limits<float>::quiet_NaN(), 0}, floor_tri).hit);
}

TEST_CASE("swept triangle-triangle: motion in the plane and parallel edges (the degenerate systems)",
          "[swept][tri_tri][coplanar]") {
    // Both triangles in y = 0, the moving one slides in the plane: the thesis's segment-plane
    // test rejects every such path (denominator 0); here it is a 2D vertex-edge contact.
    const Triangle slider{{-4, 0, 0}, {-3, 0, -0.5f}, {-3, 0, 0.5f}};
    TimeOfImpact r = sweep(slider, {4, 0, 0}, floor_tri);
    REQUIRE(r.hit);
    // Its vertex (-3, 0, -0.5) meets the edge from (-2,0,-2) to (0,0,3) at x = -1.4.
    CHECK(r.t == Approx(1.6f / 4.0f));
    CHECK(r.normal.y == Approx(0.0f).margin(1e-6));
    // Vertex sliding in the floor's plane while its triangle stands upright.
    const Triangle fin{{-4, 0, 0}, {-5, 1, 0}, {-5, 1, 1}};
    r = sweep(fin, {4, 0, 0}, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(2.8f / 4.0f));
    // Parallel edges sliding along their common line until their ends meet.
    const Triangle bar{{-6, 0, -2}, {-4, 0, -2}, {-5, 1, -2}};
    r = sweep(bar, {3, 0, 0}, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(2.0f / 3.0f));
    CHECK(r.point == glm::vec3(-2, 0, -2));
    // The contact normal is not unique here (the path grazes the Minkowski difference); it is
    // a unit vector that does not point along the motion.
    CHECK(glm::length(r.normal) == Approx(1.0f));
    CHECK(glm::dot(r.normal, glm::vec3(3, 0, 0)) <= 0.0f);
}

TEST_CASE("swept triangle-triangle agrees with the discrete Möller test on 12,000 random cases",
          "[swept][tri_tri][random]") {
    // Scale 8 bounds every coordinate involved (vertices within ~4.5, motions within ~6).
    int i = 0;
    const auto stats = testing::random_sweeps(4711, 12000, 8.0, [&i](testing::SeededRng& rng) {
        Triangle m = rng.triangle(rng.vec(-2, 2), 1.0f);
        Triangle s = rng.triangle(rng.vec(-1, 1), 1.0f);
        // Aimed roughly at the still triangle so about half the cases hit.
        const glm::vec3 aim = (s.a + s.b + s.c - m.a - m.b - m.c) / 3.0f;
        glm::vec3 motion = aim * rng.uniform(0.2f, 1.6f) + rng.vec(-0.7f, 0.7f);
        if (i++ % 5 == 0) {  // coplanar, in-plane motion: the degenerate systems
            m.a.y = m.b.y = m.c.y = s.a.y = s.b.y = s.c.y = 0.0f;
            motion.y = 0.0f;
        }
        return std::tuple{m, motion, s};
    });
    CHECK(stats.hits > 2000);
    CHECK(stats.misses > 2000);
    CHECK(stats.at_start > 200);
}

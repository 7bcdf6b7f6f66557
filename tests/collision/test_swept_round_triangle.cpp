// Sphere-triangle and ellipsoid-triangle, swept (thesis 3.2.5, 3.2.6): face, edge, vertex,
// in-plane path, start overlap, degenerate, and 10,000 random cases each against the discrete
// test.
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
const Triangle floor_tri{{-2, 0, -2}, {0, 0, 3}, {2, 0, -2}};  // y = 0, front face -y
}  // namespace

TEST_CASE("swept sphere-triangle: face from either side, edge, vertex, in-plane path", "[swept][sphere_triangle]") {
    TimeOfImpact r = sweep(Sphere{{0, 5, 0}, 1}, {0, -10, 0}, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.4f));
    CHECK(r.normal == glm::vec3(0, 1, 0));
    CHECK(r.point == glm::vec3(0, 0, 0));
    r = sweep(Sphere{{0, -5, 0}, 1}, {0, 10, 0}, floor_tri);  // from below (the back)
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.4f));
    CHECK(r.normal == glm::vec3(0, -1, 0));
    // Edge: coming down beside edge z = -2, centre at z = -2.5: touches the edge capsule.
    r = sweep(Sphere{{0, 5, -2.5f}, 1}, {0, -10, 0}, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == Approx((5.0f - std::sqrt(0.75f)) / 10.0f));
    CHECK(r.point.z == Approx(-2.0f));
    // Vertex (2, 0, -2) approached along the diagonal.
    const glm::vec3 dir = glm::normalize(glm::vec3(1, 1, -1));
    r = sweep(Sphere{glm::vec3(2, 0, -2) + dir * 5.0f, 1}, -dir * 10.0f, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.4f));
    CHECK(glm::length(r.point - glm::vec3(2, 0, -2)) < 1e-5f);
    // A path lying in the triangle's plane (the thesis's rejected case) hits the edge.
    r = sweep(Sphere{{0, 0, -6}, 1}, {0, 0, 10}, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.3f));
    CHECK(r.normal.z == Approx(-1.0f));
}

TEST_CASE("swept sphere-triangle: miss, tangent, start overlap, degenerate", "[swept][sphere_triangle]") {
    CHECK_FALSE(sweep(Sphere{{0, 5, 0}, 1}, {0, -3.9f, 0}, floor_tri).hit);
    CHECK_FALSE(sweep(Sphere{{0, 1.1f, -5}, 1}, {0, 0, 10}, floor_tri).hit);  // passes above
    CHECK(sweep(Sphere{{0, 1, -5}, 1}, {0, 0, 10}, floor_tri).hit);          // grazing the face
    TimeOfImpact r = sweep(Sphere{{0, 0.5f, 0}, 1}, {0, 10, 0}, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == 0.0f);
    CHECK(r.normal == glm::vec3(0, 1, 0));
    CHECK_FALSE(sweep(Sphere{{0, 5, 0}, 0}, {0, -10, 0}, floor_tri).hit);
    CHECK_FALSE(sweep(Sphere{{0, 5, 0}, 1}, {0, -10, 0}, Triangle{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).hit);
    CHECK_FALSE(sweep(Sphere{{0, 5, 0}, 1}, {0, k_nan, 0}, floor_tri).hit);
}

TEST_CASE("swept ellipsoid-triangle: scaling keeps the time exact", "[swept][ellipsoid]") {
    TimeOfImpact r = sweep(Ellipsoid{{0, 5, 0}, {1, 2, 1}}, {0, -10, 0}, floor_tri);
    REQUIRE(r.hit);
    CHECK(r.t == Approx(0.3f));
    CHECK(r.normal.y == Approx(1.0f));
    CHECK(glm::length(r.point) < 1e-5f);
    r = sweep(Ellipsoid{{-6, 0.5f, 0}, {3, 1, 1}}, {10, 0, 0}, floor_tri);  // long axis leads
    REQUIRE(r.hit);
    CHECK(r.t > 0.0f);
    CHECK_FALSE(sweep(Ellipsoid{{0, 5, 0}, {1, 0, 1}}, {0, -10, 0}, floor_tri).hit);
    CHECK_FALSE(sweep(Ellipsoid{{0, 5, 0}, {1, 2, 1}}, {0, -2.9f, 0}, floor_tri).hit);
}

TEST_CASE("swept sphere-triangle agrees with the discrete test on 10,000 random cases", "[swept][sphere_triangle][random]") {
    // Scale 12 bounds every coordinate and radius involved.
    const auto stats = testing::random_sweeps(21, 10000, 12.0, [](testing::SeededRng& rng) {
        const Triangle tri = rng.triangle({0, 0, 0}, 1.5f);
        const Sphere m{rng.vec(-3, 3), rng.uniform(0.05f, 1.0f)};
        return std::tuple{m, -m.center * rng.uniform(0.2f, 1.6f) + rng.vec(-1, 1), tri};
    });
    CHECK(stats.hits > 3000);
    CHECK(stats.misses > 1000);
    CHECK(stats.at_start > 100);
}

TEST_CASE("swept ellipsoid-triangle agrees with the discrete test on 10,000 random cases", "[swept][ellipsoid][random]") {
    // In scaled space coordinates grow by up to 1 / min radius = 10: scale 120.
    const auto stats = testing::random_sweeps(22, 10000, 120.0, [](testing::SeededRng& rng) {
        const Triangle tri = rng.triangle({0, 0, 0}, 1.5f);
        const Ellipsoid m{rng.vec(-3, 3), rng.vec(0.1f, 1.0f)};
        return std::tuple{m, -m.center * rng.uniform(0.2f, 1.6f) + rng.vec(-1, 1), tri};
    });
    CHECK(stats.hits > 3000);
    CHECK(stats.misses > 1000);
    CHECK(stats.at_start > 100);
}

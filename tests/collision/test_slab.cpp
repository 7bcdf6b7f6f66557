#include <catch2/catch.hpp>

#include <limits>

#include "collision/intersect.hpp"

using collision::Ray;

namespace {
glm::vec3 inverse(const glm::vec3& d) { return glm::vec3(1.0f) / d; }
}  // namespace

TEST_CASE("slab: hit, miss and the entry/exit interval", "[slab]") {
    const glm::vec3 lo(-1.0f), hi(1.0f);
    float t0 = 0, t1 = 0;
    Ray r{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    REQUIRE(collision::intersect_slab(r, inverse(r.dir), lo, hi, t0, t1));
    CHECK(t0 == Approx(4.0f));
    CHECK(t1 == Approx(6.0f));
    Ray miss{{-5.0f, 2.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    CHECK_FALSE(collision::intersect_slab(miss, inverse(miss.dir), lo, hi, t0, t1));
    Ray behind{{5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    CHECK_FALSE(collision::intersect_slab(behind, inverse(behind.dir), lo, hi, t0, t1));
}

TEST_CASE("slab: a ray lying in a face plane counts as inside (conservative), never NaN", "[slab]") {
    const glm::vec3 lo(-1.0f), hi(1.0f);
    float t0 = 0, t1 = 0;
    Ray r{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};  // y == hi.y exactly, dir.y == 0
    REQUIRE(collision::intersect_slab(r, inverse(r.dir), lo, hi, t0, t1));
    CHECK(t0 == Approx(4.0f));
    CHECK(t1 >= 6.0f);
}

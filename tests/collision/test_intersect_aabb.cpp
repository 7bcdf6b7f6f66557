// Ray-box (slab test): unit cases incl. rays in face planes and edge/corner ties, degenerate
// input, and seeded random rays against the long double reference with the bound stated in
// collision/intersect_aabb.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "float_specials.hpp"
#include "reference_check.hpp"
#include "reference_intersect.hpp"
#include "reference_sampling.hpp"

using collision::Aabb;
using collision::gamma;
using collision::Ray;
using collision::RayHit;
using reference::Real;
using reference::vec3l;
using reference::widen;

namespace {
const Aabb cube{{0.0f, 0.0f, 0.0f}, {2.0f, 2.0f, 2.0f}};
}  // namespace

TEST_CASE("aabb: hit, miss, behind, face normal", "[intersect][aabb]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cube, h));
    CHECK(h.t == 4.0f);
    CHECK(h.point == glm::vec3(-1.0f, 0.5f, 0.0f));
    CHECK(h.normal == glm::vec3(-1.0f, 0.0f, 0.0f));
    CHECK(h.uv == glm::vec2(0.75f, 0.5f));  // (y, z) fractions of the face
    REQUIRE(collision::intersect(Ray{{0.0f, 0.0f, 9.0f}, {0.0f, 0.0f, -2.0f}}, cube, h));
    CHECK(h.t == 4.0f);
    CHECK(h.normal == glm::vec3(0.0f, 0.0f, 1.0f));
    h.t = 5.0f;
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 1.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cube, h));
    CHECK_FALSE(collision::intersect(Ray{{5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cube, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.0f, 4.0f}, cube, h));
    CHECK(h.t == 5.0f);
}

TEST_CASE("aabb: a ray starting inside leaves through the far face", "[intersect][aabb]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{0.0f, 0.0f, 0.0f}, {0.0f, -0.5f, 0.0f}}, cube, h));
    CHECK(h.t == 2.0f);
    CHECK(h.normal == glm::vec3(0.0f, -1.0f, 0.0f));
    CHECK(h.point == glm::vec3(0.0f, -1.0f, 0.0f));
}

TEST_CASE("aabb: rays parallel to faces and lying in face planes", "[intersect][aabb]") {
    RayHit h;
    // In the plane y = 1 of the top face: touches the box (closed set), enters through x.
    REQUIRE(collision::intersect(Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cube, h));
    CHECK(h.t == 4.0f);
    CHECK(h.normal == glm::vec3(-1.0f, 0.0f, 0.0f));
    CHECK(h.point == glm::vec3(-1.0f, 1.0f, 0.0f));
    // Parallel just above: miss, with no NaN from 0 * inf.
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, collision::next_float_up(1.0f), 0.0f}, {1.0f, 0.0f, 0.0f}}, cube, h));
}

TEST_CASE("aabb: edge and corner hits break ties toward the lowest axis", "[intersect][aabb]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{-5.0f, -5.0f, 0.0f}, {1.0f, 1.0f, 0.0f}}, cube, h));
    CHECK(h.t == 4.0f);
    CHECK(h.normal == glm::vec3(-1.0f, 0.0f, 0.0f));
    REQUIRE(collision::intersect(Ray{{0.0f, 5.0f, 5.0f}, {0.0f, -1.0f, -1.0f}}, cube, h));
    CHECK(h.normal == glm::vec3(0.0f, 1.0f, 0.0f));
    REQUIRE(collision::intersect(Ray{{3.0f, 3.0f, 3.0f}, {-1.0f, -1.0f, -1.0f}}, cube, h));
    CHECK(h.normal == glm::vec3(1.0f, 0.0f, 0.0f));
    CHECK(h.point == glm::vec3(1.0f, 1.0f, 1.0f));
}

TEST_CASE("aabb: degenerate input is a miss, never NaN", "[intersect][aabb][degenerate]") {
    const Ray ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    RayHit h;
    h.t = 3.0f;
    CHECK_FALSE(collision::intersect(ray, Aabb{{0, 0, 0}, {0, 2, 2}}, h));
    CHECK_FALSE(collision::intersect(ray, Aabb{{0, 0, 0}, {2, -2, 2}}, h));
    CHECK_FALSE(collision::intersect(ray, Aabb{{0, 0, 0}, {2, 2, k_nan}}, h));
    CHECK_FALSE(collision::intersect(ray, Aabb{{0, 0, 0}, {2, k_inf, 2}}, h));
    CHECK_FALSE(collision::intersect(ray, Aabb{{k_nan, 0, 0}, {2, 2, 2}}, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}}, cube, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {k_nan, 0.0f, 0.0f}}, cube, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {k_inf, 0.0f, 0.0f}}, cube, h));
    CHECK_FALSE(collision::intersect(Ray{{-k_inf, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cube, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, k_nan, k_inf}, cube, h));
    CHECK(h.t == 3.0f);
}

namespace {

void check_box_case(const Ray& ray, const Aabb& box) {
    RayHit hit;
    const bool got = collision::intersect(ray, box, hit);
    const vec3l o = widen(ray.origin), d = widen(ray.dir), c = widen(box.center), size = widen(box.size);
    const vec3l lo = c - size / Real(2), hi = c + size / Real(2);
    const reference::Crossings ref = reference::box(o, d, c, size);
    reference::ShapeChecks sc;
    // collision/intersect_aabb.cpp: |dt| <= gamma(3) (|t| + |face_i| / |d_i|).
    const auto bound_at = [&](Real t, int i) {
        const Real face = std::max(std::fabs(lo[i]), std::fabs(hi[i]));
        return Real(gamma(3)) * (std::fabs(t) + face / std::fabs(d[i]));
    };
    sc.t_bound = [&](const reference::Crossing& x) {
        return bound_at(x.t, x.normal.x != 0 ? 0 : (x.normal.y != 0 ? 1 : 2));
    };
    // Hit/miss flips when the chord shrinks to nothing: both ends within their t bounds, or
    // an in-plane ray within the face's own rounding (eps |face|).
    Real tb_sum = 0;
    if (ref.enter_axis >= 0 && ref.exit_axis >= 0)
        tb_sum = bound_at(ref.enter, ref.enter_axis) + bound_at(ref.exit, ref.exit_axis);
    sc.margin_tol = tb_sum * glm::length(d) + Real(gamma(2)) * (glm::length(c) + glm::length(size));
    sc.surface_distance = [&](const vec3l& p) {
        Real outside2 = 0, inside = INFINITY;
        for (int i = 0; i < 3; ++i) {
            const Real below = lo[i] - p[i], above = p[i] - hi[i];
            const Real out = std::max({below, above, Real(0)});
            outside2 += out * out;
            inside = std::min({inside, -below, -above});
        }
        return outside2 > 0 ? std::sqrt(outside2) : inside;
    };
    // The face normal is exact, except that near an edge rounding may pick the adjacent face.
    sc.normal_tol = [&](const reference::Crossing& x, Real along) {
        const vec3l p = o + x.t * d;
        for (int j = 0; j < 3; ++j) {
            if (x.normal[j] != 0) continue;
            if (std::min(std::fabs(p[j] - lo[j]), std::fabs(p[j] - hi[j])) <= along) return Real(2);
        }
        return Real(0);
    };
    const std::string why = reference::check_answer(ray, got, hit, ref, sc);
    INFO(why);
    REQUIRE(why.empty());
}

}  // namespace

TEST_CASE("aabb: random rays agree with the long double reference within the stated bound",
          "[intersect][aabb][reference]") {
    std::mt19937_64 rng(0xaabb0001);
    sampling::Sampler sm{rng};
    const auto random_box = [&](float center_extent, float lo, float hi) {
        return Aabb{sm.point(center_extent), {sm.log_uniform(lo, hi), sm.log_uniform(lo, hi), sm.log_uniform(lo, hi)}};
    };
    const auto near_box = [&](const Aabb& b, float grow) { return b.center + 0.5f * grow * b.size * sm.point(1.0f); };
    for (int i = 0; i < 5000; ++i) {
        const Aabb b = random_box(10.0f, 0.01f, 10.0f);
        check_box_case(sm.ray_towards(b.center + sm.point(20.0f), near_box(b, 1.3f)), b);
        // Far origins.
        check_box_case(sm.ray_towards(sm.direction() * sm.log_uniform(1e3f, 1e5f), near_box(b, 1.3f)), b);
        // Huge boxes, starting inside or outside.
        const Aabb big = random_box(1e5f, 1e4f, 1e5f);
        check_box_case(sm.ray_towards(near_box(big, 3.0f), near_box(big, 1.3f)), big);
        // Axis-parallel rays (zero direction components), some in face planes exactly.
        glm::vec3 o = near_box(b, 1.5f), dir(0.0f);
        const int axis = int(sm.uniform(0.0f, 2.999f));
        dir[axis] = sm.uniform(0.0f, 1.0f) < 0.5f ? -1.0f : 1.0f;
        o[axis] = b.center[axis] - dir[axis] * b.size[axis] * 2.0f;
        if (sm.uniform(0.0f, 1.0f) < 0.3f) o[(axis + 1) % 3] = b.max()[(axis + 1) % 3];
        check_box_case(Ray{o, dir * sm.dir_scale()}, b);
        // Rays aimed exactly at edges and corners.
        glm::vec3 corner = b.min();
        for (int k = 0; k < 3; ++k)
            if (sm.uniform(0.0f, 1.0f) < 0.5f) corner[k] = b.max()[k];
        const int free_axis = int(sm.uniform(0.0f, 3.999f));  // 3: a corner
        if (free_axis < 3) corner[free_axis] = near_box(b, 1.0f)[free_axis];
        check_box_case(sm.ray_towards(b.center + sm.point(30.0f), corner), b);
    }
}

// Ray-cylinder (Y-aligned, capped): unit cases, degenerate input, seeded random rays against the
// long double reference with the bounds stated in collision/intersect_cylinder.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/surface_uv.hpp"
#include "float_specials.hpp"
#include "reference_check.hpp"
#include "reference_intersect.hpp"
#include "reference_sampling.hpp"

using collision::Cylinder;
using collision::gamma;
using collision::Ray;
using collision::RayHit;
using reference::Real;
using reference::vec3l;
using reference::widen;

namespace {
const Cylinder cyl{{0.0f, 0.0f, 0.0f}, 1.0f, 2.0f};  // y in [-1, 1]
}  // namespace

TEST_CASE("cylinder: side and cap hits with their normals", "[intersect][cylinder]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cyl, h));
    CHECK(h.t == 4.0f);
    CHECK(h.normal == glm::vec3(-1.0f, 0.0f, 0.0f));
    CHECK(h.point == glm::vec3(-1.0f, 0.5f, 0.0f));
    CHECK(collision::surface_uv(cyl, h).y == Approx(0.75f));
    REQUIRE(collision::intersect(Ray{{0.5f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, cyl, h));
    CHECK(h.t == 4.0f);
    CHECK(h.normal == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(h.point == glm::vec3(0.5f, 1.0f, 0.0f));
    REQUIRE(collision::intersect(Ray{{0.0f, -5.0f, 0.5f}, {0.0f, 2.0f, 0.0f}}, cyl, h));
    CHECK(h.t == 2.0f);
    CHECK(h.normal == glm::vec3(0.0f, -1.0f, 0.0f));
}

TEST_CASE("cylinder: miss above, beside, behind, tangent to the side", "[intersect][cylinder]") {
    RayHit h;
    h.t = 8.0f;
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 1.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cyl, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 1.5f}, {1.0f, 0.0f, 0.0f}}, cyl, h));
    CHECK_FALSE(collision::intersect(Ray{{5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cyl, h));
    CHECK_FALSE(collision::intersect(Ray{{1.5f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, cyl, h));
    CHECK(h.t == 8.0f);
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}}, cyl, h));
    CHECK(h.t == 5.0f);
    CHECK(h.normal.z == Approx(1.0f));
}

TEST_CASE("cylinder: starting inside hits the far side or cap", "[intersect][cylinder]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}, cyl, h));
    CHECK(h.t == 1.0f);
    CHECK(h.normal == glm::vec3(0.0f, 0.0f, 1.0f));
    REQUIRE(collision::intersect(Ray{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, cyl, h));
    CHECK(h.t == 1.0f);
    CHECK(h.normal == glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST_CASE("cylinder: rays parallel to the axis and in the cap planes", "[intersect][cylinder]") {
    RayHit h;
    // Parallel to the axis outside the radius: miss (no side roots to compute).
    CHECK_FALSE(collision::intersect(Ray{{2.0f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, cyl, h));
    // In the plane of the top cap (d.y = 0, y = 1): touches, enters through the rim.
    REQUIRE(collision::intersect(Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, cyl, h));
    CHECK(h.t == 4.0f);
    CHECK(h.point.y == 1.0f);
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, collision::next_float_up(1.0f), 0.0f}, {1.0f, 0.0f, 0.0f}}, cyl, h));
}

TEST_CASE("cylinder: degenerate input is a miss, never NaN", "[intersect][cylinder][degenerate]") {
    const Ray ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    RayHit h;
    h.t = 3.0f;
    CHECK_FALSE(collision::intersect(ray, Cylinder{{0, 0, 0}, 0.0f, 2.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Cylinder{{0, 0, 0}, -1.0f, 2.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Cylinder{{0, 0, 0}, 1.0f, 0.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Cylinder{{0, 0, 0}, 1.0f, k_nan}, h));
    CHECK_FALSE(collision::intersect(ray, Cylinder{{0, 0, 0}, k_inf, 2.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Cylinder{{0, k_nan, 0}, 1.0f, 2.0f}, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}}, cyl, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, k_nan, 0.0f}}, cyl, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {-k_inf, 0.0f, 0.0f}}, cyl, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, k_inf, 0.0f}, {1.0f, 0.0f, 0.0f}}, cyl, h));
    CHECK(h.t == 3.0f);
}

namespace {

void check_cylinder_case(const Ray& ray, const Cylinder& cy) {
    RayHit hit;
    const bool got = collision::intersect(ray, cy, hit);
    const vec3l o = widen(ray.origin), d = widen(ray.dir), c = widen(cy.center);
    const Real r = cy.radius, h = cy.height, ylo = c.y - h / 2, yhi = c.y + h / 2;
    const reference::Crossings ref = reference::cylinder(o, d, c, r, h);
    const glm::vec<2, Real> f2(o.x - c.x, o.z - c.z), d2(d.x, d.z);
    Real s0, s1, closest = 0, chord = 0;
    reference::detail::roots(f2, d2, r, s0, s1, closest, chord);
    const auto side_bound = [&](Real t) {
        if (chord == 0) return Real(INFINITY);
        return Real(gamma(32)) * ((glm::length(f2) + r) * (1 + r / chord) / glm::length(d2) + std::fabs(t));
    };
    const auto cap_bound = [&](Real t) {
        return Real(gamma(3)) * (std::fabs(t) + std::max(std::fabs(ylo), std::fabs(yhi)) / std::fabs(d.y));
    };
    reference::ShapeChecks sc;
    sc.t_bound = [&](const reference::Crossing& x) {
        return x.part == reference::Part::side ? side_bound(x.t) : cap_bound(x.t);
    };
    Real ends = 0;
    if (ref.enter_axis >= 0) {
        ends = (ref.enter_axis == 3 ? side_bound(ref.enter) : cap_bound(ref.enter)) +
               (ref.exit_axis == 3 ? side_bound(ref.exit) : cap_bound(ref.exit));
    }
    // Side decision: |l| within gamma(16) (|f_xz| + r) (intersect_sphere.cpp's count in 2D);
    // slab decision: the interval ends within their bounds, or an in-plane ray within the caps'
    // rounding.
    sc.margin_tol = Real(gamma(16)) * (glm::length(f2) + r) + ends * glm::length(d) +
                    Real(gamma(2)) * (std::fabs(c.y) + h);
    sc.surface_distance = [&](const vec3l& p) {
        const Real rho = std::hypot(p.x - c.x, p.z - c.z);
        const Real out_r = std::max(rho - r, Real(0)), out_y = std::max({ylo - p.y, p.y - yhi, Real(0)});
        if (out_r > 0 || out_y > 0) return std::hypot(out_r, out_y);
        return std::min({r - rho, p.y - ylo, yhi - p.y});
    };
    sc.normal_tol = [&](const reference::Crossing& x, Real along) {
        const vec3l p = o + x.t * d;
        const bool near_rim = std::min(std::fabs(p.y - ylo), std::fabs(p.y - yhi)) <= along &&
                              std::fabs(std::hypot(p.x - c.x, p.z - c.z) - r) <= along;
        if (near_rim) return Real(2);
        return x.part == reference::Part::side ? along / r + Real(gamma(8)) : Real(0);
    };
    const std::string why = reference::check_answer(ray, got, hit, ref, sc);
    INFO(why);
    REQUIRE(why.empty());
}

}  // namespace

TEST_CASE("cylinder: random rays agree with the long double reference within the stated bound",
          "[intersect][cylinder][reference]") {
    std::mt19937_64 rng(0xc71d0001);
    sampling::Sampler sm{rng};
    const auto near = [&](const Cylinder& c, float grow) {
        return c.center + grow * glm::vec3(c.radius, 0.5f * c.height, c.radius) * sm.point(1.0f);
    };
    for (int i = 0; i < 5000; ++i) {
        const Cylinder c{sm.point(10.0f), sm.log_uniform(0.01f, 10.0f), sm.log_uniform(0.01f, 10.0f)};
        check_cylinder_case(sm.ray_towards(c.center + sm.point(20.0f), near(c, 1.3f)), c);
        check_cylinder_case(sm.ray_towards(sm.direction() * sm.log_uniform(1e3f, 1e5f), near(c, 1.3f)), c);
        const Cylinder big{sm.point(1e5f), 1e5f * sm.uniform(0.5f, 1.0f), 1e5f * sm.uniform(0.1f, 2.0f)};
        check_cylinder_case(sm.ray_towards(near(big, 3.0f), near(big, 1.3f)), big);
        // Grazing the side: closest approach to the axis at r (1 +- 10^-k), horizontal.
        const float closest = c.radius * (1.0f + (sm.uniform(0.0f, 1.0f) < 0.5f ? -1.0f : 1.0f) *
                                                     std::pow(10.0f, -sm.uniform(1.0f, 7.0f)));
        const glm::vec3 u = glm::normalize(glm::vec3(sm.uniform(-1.0f, 1.0f), 0.0f, sm.uniform(-1.0f, 1.0f)));
        const glm::vec3 side(-u.z, 0.0f, u.x);
        const glm::vec3 p = c.center + side * closest + glm::vec3(0.0f, sm.uniform(-0.6f, 0.6f) * c.height, 0.0f);
        check_cylinder_case(Ray{p - u * (c.radius * sm.log_uniform(1.5f, 1e3f)), u * sm.dir_scale()}, c);
        // Parallel to the axis, and horizontal rays at cap height.
        const glm::vec3 q = near(c, 1.2f);
        check_cylinder_case(Ray{{q.x, c.center.y - 3.0f * c.height, q.z}, {0.0f, sm.dir_scale(), 0.0f}}, c);
        check_cylinder_case(Ray{{q.x - 5.0f * c.radius, c.center.y + 0.5f * c.height, q.z},
                                {sm.dir_scale(), 0.0f, 0.0f}},
                            c);
    }
}

// Ray-ellipsoid: unit cases, degenerate input, seeded random rays against the long double
// reference with the bounds stated in collision/intersect_ellipsoid.cpp.
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

using collision::Ellipsoid;
using collision::gamma;
using collision::Ray;
using collision::RayHit;
using reference::Real;
using reference::vec3l;
using reference::widen;

namespace {
const Ellipsoid egg{{1.0f, 0.0f, 0.0f}, {2.0f, 1.0f, 0.5f}};
}  // namespace

TEST_CASE("ellipsoid: hits along the axes, normals by the inverse transpose", "[intersect][ellipsoid]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, egg, h));
    CHECK(h.t == 4.0f);
    CHECK(h.normal == glm::vec3(-1.0f, 0.0f, 0.0f));
    REQUIRE(collision::intersect(Ray{{1.0f, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f}}, egg, h));
    CHECK(h.t == 2.5f);
    CHECK(h.normal == glm::vec3(0.0f, 0.0f, 1.0f));
    // Off-axis: at p = c + (2 cos a, sin a, 0) the normal is along (cos a / 2, sin a, 0).
    const float a = 0.7f;
    const glm::vec3 p = egg.center + glm::vec3(2.0f * std::cos(a), std::sin(a), 0.0f);
    REQUIRE(collision::intersect(Ray{p + glm::vec3(0.0f, 5.0f, 0.0f), {0.0f, -1.0f, 0.0f}}, egg, h));
    CHECK(h.t == Approx(5.0f));
    const glm::vec3 n = glm::normalize(glm::vec3(std::cos(a) / 2.0f, std::sin(a), 0.0f));
    CHECK(glm::length(h.normal - n) < 1e-5f);
}

TEST_CASE("ellipsoid: miss, tangent, inside", "[intersect][ellipsoid]") {
    RayHit h;
    h.t = 4.0f;
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 1.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, egg, h));
    CHECK_FALSE(collision::intersect(Ray{{5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, egg, h));
    CHECK(h.t == 4.0f);
    REQUIRE(collision::intersect(Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, egg, h));
    CHECK(h.t == 6.0f);
    REQUIRE(collision::intersect(Ray{{1.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}}, egg, h));
    CHECK(h.t == 0.5f);
    CHECK(h.normal == glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST_CASE("ellipsoid: degenerate input is a miss, never NaN", "[intersect][ellipsoid][degenerate]") {
    const Ray ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    RayHit h;
    h.t = 3.0f;
    CHECK_FALSE(collision::intersect(ray, Ellipsoid{{0, 0, 0}, {1, 0, 1}}, h));
    CHECK_FALSE(collision::intersect(ray, Ellipsoid{{0, 0, 0}, {1, 1, -1}}, h));
    CHECK_FALSE(collision::intersect(ray, Ellipsoid{{0, 0, 0}, {k_nan, 1, 1}}, h));
    CHECK_FALSE(collision::intersect(ray, Ellipsoid{{0, 0, 0}, {1, k_inf, 1}}, h));
    CHECK_FALSE(collision::intersect(ray, Ellipsoid{{0, k_nan, 0}, {1, 1, 1}}, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}}, egg, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {k_inf, 0.0f, 0.0f}}, egg, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, k_nan, 0.0f}, {1.0f, 0.0f, 0.0f}}, egg, h));
    CHECK(h.t == 3.0f);
}

namespace {

void check_ellipsoid_case(const Ray& ray, const Ellipsoid& e) {
    RayHit hit;
    const bool got = collision::intersect(ray, e, hit);
    const vec3l o = widen(ray.origin), d = widen(ray.dir), c = widen(e.center), radii = widen(e.radii);
    const reference::Crossings ref = reference::ellipsoid(o, d, c, radii);
    const vec3l fs = (o - c) / radii, ds = d / radii;
    reference::ShapeChecks sc;
    // collision/intersect_ellipsoid.cpp: gamma(40) ((|f'| + 1)(1 + 1 / h') / |d'| + |t|).
    sc.t_bound = [&](const reference::Crossing& x) {
        if (x.half_chord == 0) return Real(INFINITY);
        return Real(gamma(40)) * ((glm::length(fs) + 1) * (1 + 1 / x.half_chord) / glm::length(ds) + std::fabs(x.t));
    };
    sc.margin_tol = Real(gamma(20)) * (glm::length(fs) + 1);  // the sphere's gamma(16) + scaling
    // Distance to the surface to first order: |F| / |grad F| with F = |(p - c) / radii| - 1.
    sc.surface_distance = [&](const vec3l& p) {
        const vec3l q = (p - c) / radii;
        const Real ql = glm::length(q);
        return std::fabs(ql - 1) / glm::length(q / ql / radii);
    };
    // The normal turns at most by the largest curvature max(radii) / min(radii)^2 per length.
    const Real rmax = std::max({radii.x, radii.y, radii.z}), rmin = std::min({radii.x, radii.y, radii.z});
    sc.normal_tol = [&](const reference::Crossing&, Real along) { return along * rmax / (rmin * rmin) + Real(gamma(12)); };
    sc.reprojection_factor = rmax / rmin;
    const std::string why = reference::check_answer(ray, got, hit, ref, sc);
    INFO(why);
    REQUIRE(why.empty());
}

}  // namespace

TEST_CASE("ellipsoid: random rays agree with the long double reference within the stated bound",
          "[intersect][ellipsoid][reference]") {
    std::mt19937_64 rng(0xe1150001);
    sampling::Sampler sm{rng};
    const auto random_radii = [&](float lo, float hi) {
        return glm::vec3(sm.log_uniform(lo, hi), sm.log_uniform(lo, hi), sm.log_uniform(lo, hi));
    };
    const auto near = [&](const Ellipsoid& e, float grow) { return e.center + grow * e.radii * sm.point(1.0f); };
    for (int i = 0; i < 8000; ++i) {
        const Ellipsoid e{sm.point(10.0f), random_radii(0.01f, 10.0f)};
        check_ellipsoid_case(sm.ray_towards(e.center + sm.point(20.0f), near(e, 1.0f)), e);
        check_ellipsoid_case(sm.ray_towards(sm.direction() * sm.log_uniform(1e3f, 1e5f), near(e, 1.0f)), e);
        const Ellipsoid big{sm.point(1e5f), random_radii(1e4f, 1e5f)};
        check_ellipsoid_case(sm.ray_towards(near(big, 2.0f), near(big, 1.0f)), big);
    }
}

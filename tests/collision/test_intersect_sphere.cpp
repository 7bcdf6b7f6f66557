// Ray-sphere: unit cases, degenerate input, and seeded random rays against the long double
// reference with the bounds stated in collision/intersect_sphere.cpp.
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

using collision::gamma;
using collision::Ray;
using collision::RayHit;
using collision::Sphere;
using reference::Real;
using reference::widen;


TEST_CASE("sphere: hit from outside, miss, behind", "[intersect][sphere]") {
    const Sphere s{{0.0f, 0.0f, 0.0f}, 1.0f};
    RayHit h;
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, s, h));
    CHECK(h.t == 4.0f);
    CHECK(h.point == glm::vec3(-1.0f, 0.0f, 0.0f));
    CHECK(h.normal == glm::vec3(-1.0f, 0.0f, 0.0f));
    CHECK(h.uv == glm::vec2(0.0f));  // uv only on request:
    CHECK(collision::surface_uv(s, h).x == Approx(0.5f));  // phi = pi
    CHECK(collision::surface_uv(s, h).y == Approx(0.5f));  // theta = pi / 2
    // A non-unit direction scales t.
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f}}, s, h));
    CHECK(h.t == 1.0f);
    RayHit untouched;
    untouched.t = 123.0f;
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 1.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, s, untouched));
    CHECK_FALSE(collision::intersect(Ray{{5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, s, untouched));
    CHECK(untouched.t == 123.0f);
}

TEST_CASE("sphere: tangent ray touches once, a hair outside misses", "[intersect][sphere]") {
    const Sphere s{{0.0f, 0.0f, 0.0f}, 1.0f};
    RayHit h;
    REQUIRE(collision::intersect(Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, s, h));
    CHECK(h.t == 5.0f);
    CHECK(h.normal.y == Approx(1.0f));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, collision::next_float_up(1.0f), 0.0f}, {1.0f, 0.0f, 0.0f}}, s, h));
}

TEST_CASE("sphere: a ray starting inside hits the far side, normal outward", "[intersect][sphere]") {
    const Sphere s{{1.0f, 2.0f, 3.0f}, 2.0f};
    RayHit h;
    REQUIRE(collision::intersect(Ray{{1.0f, 2.0f, 3.0f}, {0.0f, 0.0f, -1.0f}}, s, h));
    CHECK(h.t == 2.0f);
    CHECK(h.normal == glm::vec3(0.0f, 0.0f, -1.0f));
    CHECK(h.point == glm::vec3(1.0f, 2.0f, 1.0f));
}

TEST_CASE("sphere: tmin and tmax select the crossing", "[intersect][sphere]") {
    const Sphere s{{0.0f, 0.0f, 0.0f}, 1.0f};
    RayHit h;
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 4.5f, k_inf}, s, h));
    CHECK(h.t == 6.0f);
    CHECK(h.normal.x == 1.0f);
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.0f, 4.0f}, s, h));
    // A swept segment that stops short.
    CHECK_FALSE(collision::intersect(collision::segment({-5.0f, 0.0f, 0.0f}, {-2.0f, 0.0f, 0.0f}), s, h));
    REQUIRE(collision::intersect(collision::segment({-5.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}), s, h));
    CHECK(h.t == Approx(0.8f));
}

TEST_CASE("sphere: degenerate input is a miss, never NaN", "[intersect][sphere][degenerate]") {
    const Ray ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    RayHit h;
    h.t = 7.0f;
    CHECK_FALSE(collision::intersect(ray, Sphere{{0.0f, 0.0f, 0.0f}, 0.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Sphere{{0.0f, 0.0f, 0.0f}, -1.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Sphere{{0.0f, 0.0f, 0.0f}, k_nan}, h));
    CHECK_FALSE(collision::intersect(ray, Sphere{{0.0f, 0.0f, 0.0f}, k_inf}, h));
    CHECK_FALSE(collision::intersect(ray, Sphere{{k_nan, 0.0f, 0.0f}, 1.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Sphere{{k_inf, 0.0f, 0.0f}, 1.0f}, h));
    const Sphere s{{0.0f, 0.0f, 0.0f}, 1.0f};
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}}, s, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {k_nan, 0.0f, 0.0f}}, s, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {k_inf, 0.0f, 0.0f}}, s, h));
    CHECK_FALSE(collision::intersect(Ray{{k_nan, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, s, h));
    CHECK_FALSE(collision::intersect(Ray{{-k_inf, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, s, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, k_nan, k_inf}, s, h));
    CHECK(h.t == 7.0f);
}

namespace {

// Stated bound on t (collision/intersect_sphere.cpp), evaluated with exact quantities.
Real sphere_t_bound(const Ray& ray, const Sphere& s, Real t) {
    const auto o = widen(ray.origin), d = widen(ray.dir), c = widen(s.center);
    const Real r = s.radius;
    const Real f = glm::length(o - c);
    const Real h = reference::sphere_half_chord(o, d, c, r);
    if (h == 0) return std::numeric_limits<Real>::infinity();
    return Real(gamma(32)) * ((f + r) * (1 + r / h) / glm::length(d) + std::fabs(t));
}

// Hit/miss is decided on r - |l| with |l| off by at most gamma(11) |f| + gamma(3) r (counted in
// the sphere's header); rounded up to gamma(16) (|f| + r).
Real sphere_margin_tol(const Ray& ray, const Sphere& s) {
    return Real(gamma(16)) * (glm::length(widen(ray.origin) - widen(s.center)) + Real(s.radius));
}

void check_sphere_case(const Ray& ray, const Sphere& s) {
    RayHit hit;
    const bool got = collision::intersect(ray, s, hit);
    const auto o = widen(ray.origin), d = widen(ray.dir), c = widen(s.center);
    const Real r = s.radius;
    const reference::Crossings ref = reference::sphere(o, d, c, r);
    const auto bound = [&](const reference::Crossing& x) { return sphere_t_bound(ray, s, x.t); };
    const reference::Verdict v = reference::judge(got, hit, ref, ray.tmin, ray.tmax, bound, sphere_margin_tol(ray, s));
    INFO(v.why);
    REQUIRE(v.ok);
    if (!got) return;
    REQUIRE(std::isfinite(hit.t));
    // The point lies on the sphere within its stated per-axis bound.
    const Real surface_distance = std::fabs(glm::length(widen(hit.point) - c) - r);
    REQUIRE(surface_distance <= glm::length(widen(hit.point_error)));
    // Along the surface it is as good as t: within the t bound of the exact point, plus the
    // rounding of o + t d (gamma(3) (|o| + |t d|)), counted twice because re-projection moves
    // the point by at most its distance from the surface, plus the stated point error.
    if (v.matched != nullptr) {
        const Real tb = bound(*v.matched);
        const Real dl = glm::length(d);
        const Real along = 2 * (tb * dl + Real(gamma(3)) * (glm::length(o) + std::fabs(v.matched->t) * dl)) +
                           glm::length(widen(hit.point_error));
        const auto exact_point = o + v.matched->t * d;
        REQUIRE(glm::length(widen(hit.point) - exact_point) <= along);
        REQUIRE(glm::length(widen(hit.normal) - v.matched->normal) <= along / r + Real(gamma(8)));
    }
    REQUIRE(std::fabs(glm::length(widen(hit.normal)) - 1) <= Real(gamma(8)));
}

}  // namespace

TEST_CASE("sphere: random rays agree with the long double reference within the stated bound",
          "[intersect][sphere][reference]") {
    std::mt19937_64 rng(0x5a1e0001);
    sampling::Sampler sm{rng};
    for (int i = 0; i < 20000; ++i) {
        // Moderate scenes: sphere and origin within a few radii.
        const Sphere s{sm.point(10.0f), sm.log_uniform(0.01f, 10.0f)};
        const glm::vec3 o = s.center + sm.direction() * (s.radius * sm.log_uniform(0.01f, 20.0f));
        const glm::vec3 target = s.center + sm.direction() * (s.radius * sm.uniform(0.0f, 1.5f));
        check_sphere_case(sm.ray_towards(o, target), s);
    }
}

TEST_CASE("sphere: far origins (|o| up to 1e5) and huge spheres (radius 1e5) meet the bound",
          "[intersect][sphere][reference]") {
    std::mt19937_64 rng(0x5a1e0002);
    sampling::Sampler sm{rng};
    for (int i = 0; i < 10000; ++i) {
        const Sphere small{sm.point(10.0f), sm.log_uniform(0.1f, 10.0f)};
        const glm::vec3 o = sm.direction() * sm.log_uniform(1e3f, 1e5f);
        check_sphere_case(sm.ray_towards(o, small.center + sm.direction() * (small.radius * sm.uniform(0.0f, 1.2f))),
                          small);
        const Sphere huge{sm.point(1e5f), 1e5f * sm.uniform(0.5f, 1.0f)};
        // Origins inside and outside the huge sphere, near its surface and far away.
        const glm::vec3 o2 = huge.center + sm.direction() * (huge.radius * sm.uniform(0.0f, 3.0f));
        check_sphere_case(sm.ray_towards(o2, huge.center + sm.direction() * (huge.radius * sm.uniform(0.0f, 1.2f))),
                          huge);
    }
}

TEST_CASE("sphere: grazing rays near the tangent meet the bound", "[intersect][sphere][reference]") {
    std::mt19937_64 rng(0x5a1e0003);
    sampling::Sampler sm{rng};
    for (int i = 0; i < 10000; ++i) {
        const Sphere s{sm.point(100.0f), sm.log_uniform(0.1f, 1e4f)};
        // Closest approach at r (1 +- 10^-k), k up to 7: from clear chords down to float resolution.
        const float closest = s.radius * (1.0f + (sm.uniform(0.0f, 1.0f) < 0.5f ? -1.0f : 1.0f) *
                                                     std::pow(10.0f, -sm.uniform(1.0f, 7.0f)));
        check_sphere_case(sm.grazing_ray(s.center, closest, s.radius * sm.log_uniform(1.5f, 1e3f)), s);
    }
}

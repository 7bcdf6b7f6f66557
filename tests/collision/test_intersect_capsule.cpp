// Ray-capsule (Y-aligned and oriented): unit cases, degenerate input, seeded random rays against
// the long double reference with the bounds stated in collision/intersect_capsule.cpp and
// collision/intersect_oriented_capsule.cpp.
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

using collision::Capsule;
using collision::gamma;
using collision::OrientedCapsule;
using collision::Ray;
using collision::RayHit;
using reference::Real;
using reference::vec3l;
using reference::widen;

namespace {
const Capsule bean{{0.0f, 0.0f, 0.0f}, 1.0f, 2.0f};  // axis y in [-1, 1], total extent [-2, 2]
}  // namespace

TEST_CASE("capsule: side and end-sphere hits with their normals", "[intersect][capsule]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, bean, h));
    CHECK(h.t == 4.0f);
    CHECK(h.normal == glm::vec3(-1.0f, 0.0f, 0.0f));
    REQUIRE(collision::intersect(Ray{{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, bean, h));
    CHECK(h.t == 3.0f);
    CHECK(h.normal == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(collision::surface_uv(bean, h).y == 1.0f);
    // Through the lower hemisphere at 45 degrees: point (0, -1 - s, s) with s = 1 / sqrt 2.
    const float s = std::sqrt(0.5f);
    REQUIRE(collision::intersect(Ray{{0.0f, -1.0f - s, 5.0f}, {0.0f, 0.0f, -1.0f}}, bean, h));
    CHECK(h.t == Approx(5.0f - s));
    CHECK(h.normal.y == Approx(-s));
    CHECK(h.normal.z == Approx(s));
}

TEST_CASE("capsule: misses, tangents, inside, parallel to the axis", "[intersect][capsule]") {
    RayHit h;
    h.t = 8.0f;
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 1.5f}, {1.0f, 0.0f, 0.0f}}, bean, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 2.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, bean, h));
    CHECK_FALSE(collision::intersect(Ray{{1.5f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, bean, h));
    CHECK(h.t == 8.0f);
    // Tangent to the top of the upper sphere.
    REQUIRE(collision::intersect(Ray{{-5.0f, 2.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, bean, h));
    CHECK(h.t == 5.0f);
    // Inside: far side.
    REQUIRE(collision::intersect(Ray{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, bean, h));
    CHECK(h.t == 2.0f);
    CHECK(h.normal == glm::vec3(0.0f, 1.0f, 0.0f));
    // Parallel to the axis, off-centre: enters the bottom sphere.
    REQUIRE(collision::intersect(Ray{{0.6f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, bean, h));
    CHECK(h.t == Approx(5.0f - 1.0f - 0.8f));
    CHECK(h.normal.x == Approx(0.6f));
    // Height 0 is a sphere.
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, Capsule{{0, 0, 0}, 1.0f, 0.0f}, h));
    CHECK(h.t == 4.0f);
}

TEST_CASE("oriented capsule: matches the Y-aligned one when aligned, and rotated cases",
          "[intersect][capsule][oriented]") {
    RayHit a, b;
    const OrientedCapsule up{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1.0f};
    for (const Ray& ray : {Ray{{-5.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, Ray{{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}},
                           Ray{{0.3f, -5.0f, 0.2f}, {0.0f, 1.0f, 0.0f}}, Ray{{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}}}) {
        REQUIRE(collision::intersect(ray, bean, a));
        REQUIRE(collision::intersect(ray, up, b));
        CHECK(b.t == Approx(a.t).epsilon(1e-6));
        CHECK(glm::length(b.normal - a.normal) < 1e-6f);
    }
    // Along x, the thesis's special case (axis parallel to (0,1,0) x dir... here: any axis).
    const OrientedCapsule along_x{{-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f};
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, along_x, b));
    CHECK(b.t == Approx(3.5f));
    CHECK(b.normal.x == Approx(-1.0f));
    const OrientedCapsule down{{0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f};  // axis -y: no special case
    REQUIRE(collision::intersect(Ray{{0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, down, b));
    CHECK(b.t == Approx(3.0f));
    // a == b is a sphere.
    REQUIRE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, OrientedCapsule{{}, {}, 1.0f}, b));
    CHECK(b.t == 4.0f);
}

TEST_CASE("capsule: degenerate input is a miss, never NaN", "[intersect][capsule][degenerate]") {
    const Ray ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    RayHit h;
    h.t = 3.0f;
    CHECK_FALSE(collision::intersect(ray, Capsule{{0, 0, 0}, 0.0f, 2.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Capsule{{0, 0, 0}, 1.0f, -1.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Capsule{{0, 0, 0}, k_nan, 2.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Capsule{{0, 0, 0}, 1.0f, k_inf}, h));
    CHECK_FALSE(collision::intersect(ray, Capsule{{k_inf, 0, 0}, 1.0f, 1.0f}, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}}, bean, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {k_nan, 0.0f, 0.0f}}, bean, h));
    CHECK_FALSE(collision::intersect(Ray{{k_nan, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, bean, h));
    CHECK_FALSE(collision::intersect(ray, OrientedCapsule{{0, 0, 0}, {0, 1, 0}, 0.0f}, h));
    CHECK_FALSE(collision::intersect(ray, OrientedCapsule{{0, 0, 0}, {0, k_nan, 0}, 1.0f}, h));
    CHECK_FALSE(collision::intersect(ray, OrientedCapsule{{k_inf, 0, 0}, {0, 1, 0}, 1.0f}, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}},
                                     OrientedCapsule{{0, 0, 0}, {0, 1, 0}, 1.0f}, h));
    CHECK(h.t == 3.0f);
}

namespace {

// Checks one ray against the capsule around a-b; `gamma_n`, `extra` and `side_dir` parametrise
// the stated bound: gamma(gamma_n) ((|o - ref| + r + extra)(1 + r / h) / |d_part| + |t|).
void check_capsule_answer(const Ray& ray, bool got, const RayHit& hit, const vec3l& la, const vec3l& lb, Real r,
                          int gamma_n, Real extra, const vec3l& ref_point) {
    const vec3l o = widen(ray.origin), d = widen(ray.dir);
    const reference::Crossings ref = reference::capsule(o, d, la, lb, r);
    const vec3l w = lb - la;
    const vec3l u = glm::dot(w, w) > 0 ? glm::normalize(w) : vec3l(0, 1, 0);
    const Real f = glm::length(o - ref_point);
    reference::ShapeChecks sc;
    sc.t_bound = [&](const reference::Crossing& x) {
        if (x.half_chord == 0) return Real(INFINITY);
        const Real d_part =
            x.part == reference::Part::side ? glm::length(d - glm::dot(d, u) * u) : glm::length(d);
        const Real size = x.part == reference::Part::side ? f + r + extra : glm::length(o - x.center) + r + extra;
        return Real(gamma(gamma_n)) * (size * (1 + r / x.half_chord) / d_part + std::fabs(x.t));
    };
    // Hit/miss: the closest-approach distances within gamma(16) of their sizes (the sphere's
    // count), doubled for the frame change of the oriented capsule (gamma_n / 2).
    sc.margin_tol = Real(gamma(gamma_n / 2)) * (f + r + extra);
    sc.surface_distance = [&](const vec3l& p) {
        const Real s = glm::dot(w, w) > 0 ? std::clamp(glm::dot(p - la, w) / glm::dot(w, w), Real(0), Real(1)) : 0;
        return std::fabs(glm::length(p - (la + s * w)) - r);
    };
    sc.normal_tol = [&](const reference::Crossing&, Real along) { return along / r + Real(gamma(8)); };
    const std::string why = reference::check_answer(ray, got, hit, ref, sc);
    INFO(why);
    REQUIRE(why.empty());
}

void check_capsule_case(const Ray& ray, const Capsule& c) {
    RayHit hit;
    const bool got = collision::intersect(ray, c, hit);
    // The end points exactly (centre +- height / 2 in long double); the stated bound's extra
    // size |e| of the ends is covered by |c| + height.
    const vec3l cc = widen(c.center), hh(0, Real(c.height) / 2, 0);
    check_capsule_answer(ray, got, hit, cc - hh, cc + hh, c.radius, 32, glm::length(cc) + Real(c.height), cc);
}

void check_oriented_case(const Ray& ray, const OrientedCapsule& c) {
    RayHit hit;
    const bool got = collision::intersect(ray, c, hit);
    const vec3l m = (widen(c.a) + widen(c.b)) / Real(2);
    check_capsule_answer(ray, got, hit, widen(c.a), widen(c.b), c.radius, 64, glm::length(m) + glm::length(widen(c.b) - widen(c.a)),
                         m);
}

}  // namespace

TEST_CASE("capsule: random rays agree with the long double reference within the stated bound",
          "[intersect][capsule][reference]") {
    std::mt19937_64 rng(0xca950001);
    sampling::Sampler sm{rng};
    const auto near = [&](const Capsule& c, float grow) {
        return c.center + grow * glm::vec3(c.radius, 0.5f * c.height + c.radius, c.radius) * sm.point(1.0f);
    };
    for (int i = 0; i < 5000; ++i) {
        const Capsule c{sm.point(10.0f), sm.log_uniform(0.01f, 10.0f), sm.log_uniform(0.01f, 10.0f)};
        check_capsule_case(sm.ray_towards(c.center + sm.point(20.0f), near(c, 1.3f)), c);
        check_capsule_case(sm.ray_towards(sm.direction() * sm.log_uniform(1e3f, 1e5f), near(c, 1.3f)), c);
        const Capsule big{sm.point(1e5f), 1e5f * sm.uniform(0.5f, 1.0f), 1e5f * sm.uniform(0.0f, 2.0f)};
        check_capsule_case(sm.ray_towards(near(big, 3.0f), near(big, 1.3f)), big);
        // Grazing the end spheres and the side.
        const float closest = c.radius * (1.0f + (sm.uniform(0.0f, 1.0f) < 0.5f ? -1.0f : 1.0f) *
                                                     std::pow(10.0f, -sm.uniform(1.0f, 7.0f)));
        const glm::vec3 end = c.center + glm::vec3(0.0f, (sm.uniform(0.0f, 1.0f) < 0.5f ? -0.5f : 0.5f) * c.height, 0.0f);
        check_capsule_case(sm.grazing_ray(end, closest, c.radius * sm.log_uniform(1.5f, 1e3f)), c);
        const glm::vec3 q = near(c, 1.2f);
        check_capsule_case(Ray{{q.x, c.center.y - 3.0f * (c.height + c.radius), q.z}, {0.0f, sm.dir_scale(), 0.0f}}, c);
    }
}

TEST_CASE("oriented capsule: random rays agree with the long double reference within the stated bound",
          "[intersect][capsule][oriented][reference]") {
    std::mt19937_64 rng(0xca950002);
    sampling::Sampler sm{rng};
    const auto near = [&](const OrientedCapsule& c, float grow) {
        const float s = sm.uniform(-0.2f, 1.2f);
        return c.a + s * (c.b - c.a) + sm.direction() * (c.radius * grow * sm.uniform(0.0f, 1.0f));
    };
    for (int i = 0; i < 5000; ++i) {
        const glm::vec3 a = sm.point(10.0f);
        const OrientedCapsule c{a, a + sm.direction() * sm.log_uniform(0.01f, 10.0f), sm.log_uniform(0.01f, 10.0f)};
        check_oriented_case(sm.ray_towards(a + sm.point(20.0f), near(c, 1.3f)), c);
        check_oriented_case(sm.ray_towards(sm.direction() * sm.log_uniform(1e3f, 1e5f), near(c, 1.3f)), c);
        const glm::vec3 ba = sm.point(1e5f);
        const OrientedCapsule big{ba, ba + sm.direction() * sm.uniform(0.0f, 2e5f), 1e5f * sm.uniform(0.5f, 1.0f)};
        check_oriented_case(sm.ray_towards(near(big, 3.0f), near(big, 1.3f)), big);
        // Axis-parallel rays, and axes along the coordinate axes (the thesis's special case).
        const glm::vec3 u = glm::normalize(c.b - c.a);
        check_oriented_case(Ray{near(c, 1.2f) - u * (30.0f * c.radius + 30.0f), u * sm.dir_scale()}, c);
        glm::vec3 axis(0.0f);
        axis[i % 3] = (i / 3) % 2 ? 1.0f : -1.0f;
        const OrientedCapsule aligned{a, a + axis * sm.log_uniform(0.1f, 10.0f), sm.log_uniform(0.1f, 10.0f)};
        check_oriented_case(sm.ray_towards(a + sm.point(20.0f), near(aligned, 1.3f)), aligned);
    }
}

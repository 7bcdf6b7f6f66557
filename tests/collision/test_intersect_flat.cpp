// Ray-plane, ray-disk, ray-quad: unit cases (parallel rays, rims and edges), degenerate input,
// seeded random rays against the long double reference with the bounds stated in
// collision/ray_plane.hpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "reference_check.hpp"
#include "reference_intersect.hpp"
#include "reference_sampling.hpp"

using collision::Disk;
using collision::gamma;
using collision::Plane;
using collision::Quad;
using collision::Ray;
using collision::RayHit;
using reference::Real;
using reference::vec3l;
using reference::widen;

namespace {
constexpr float k_inf = std::numeric_limits<float>::infinity();
constexpr float k_nan = std::numeric_limits<float>::quiet_NaN();
const Plane ground{{0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
const Disk lid{{0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 2.0f};
const Quad wall{{0.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};  // normal +z
}  // namespace

TEST_CASE("plane: hits from both sides, unflipped normal, parallel rays miss", "[intersect][plane]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{3.0f, 5.0f, 0.0f}, {0.0f, -2.0f, 0.0f}}, ground, h));
    CHECK(h.t == 2.0f);
    CHECK(h.point == glm::vec3(3.0f, 1.0f, 0.0f));
    CHECK(h.normal == glm::vec3(0.0f, 1.0f, 0.0f));
    REQUIRE(collision::intersect(Ray{{3.0f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, ground, h));
    CHECK(h.t == 6.0f);
    CHECK(h.normal == glm::vec3(0.0f, 1.0f, 0.0f));
    h.t = 9.0f;
    CHECK_FALSE(collision::intersect(Ray{{3.0f, 5.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, ground, h));  // parallel
    CHECK_FALSE(collision::intersect(Ray{{3.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, ground, h));  // in the plane
    CHECK_FALSE(collision::intersect(Ray{{3.0f, 5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, ground, h));  // away
    CHECK_FALSE(collision::intersect(Ray{{3.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.0f, 4.0f}, ground, h));
    CHECK(h.t == 9.0f);
    // A ray starting on the plane does not hit it at t = 0 (t must exceed tmin).
    CHECK_FALSE(collision::intersect(Ray{{3.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, ground, h));
}

TEST_CASE("disk: inside, rim, outside", "[intersect][disk]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{1.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}}, lid, h));
    CHECK(h.t == 4.0f);
    CHECK(h.uv.x == 0.5f);
    REQUIRE(collision::intersect(Ray{{0.0f, 5.0f, 2.0f}, {0.0f, -1.0f, 0.0f}}, lid, h));  // on the rim
    CHECK(h.uv.x == 1.0f);
    CHECK_FALSE(collision::intersect(Ray{{0.0f, 5.0f, collision::next_float_up(2.0f)}, {0.0f, -1.0f, 0.0f}}, lid, h));
    CHECK_FALSE(collision::intersect(Ray{{-5.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, lid, h));  // in its plane
}

TEST_CASE("quad: inside with (s, t), edges and corners belong to it, outside", "[intersect][quad]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{0.5f, 0.25f, 3.0f}, {0.0f, 0.0f, -1.0f}}, wall, h));
    CHECK(h.t == 3.0f);
    CHECK(h.uv == glm::vec2(0.25f, 0.25f));
    CHECK(h.normal == glm::vec3(0.0f, 0.0f, 1.0f));
    REQUIRE(collision::intersect(Ray{{2.0f, 1.0f, 3.0f}, {0.0f, 0.0f, -1.0f}}, wall, h));
    CHECK(h.uv == glm::vec2(1.0f, 1.0f));
    REQUIRE(collision::intersect(Ray{{0.0f, 0.5f, -3.0f}, {0.0f, 0.0f, 1.0f}}, wall, h));
    CHECK(h.normal == glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK_FALSE(collision::intersect(Ray{{collision::next_float_up(2.0f), 0.5f, 3.0f}, {0.0f, 0.0f, -1.0f}}, wall, h));
    CHECK_FALSE(collision::intersect(Ray{{-1.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f}}, wall, h));  // in its plane
}

TEST_CASE("flat shapes: degenerate input is a miss, never NaN", "[intersect][plane][disk][quad][degenerate]") {
    const Ray ray{{0.5f, 0.5f, 3.0f}, {0.0f, 0.0f, -1.0f}};
    RayHit h;
    h.t = 3.0f;
    CHECK_FALSE(collision::intersect(ray, Plane{{0, 0, 0}, {0, 0, 0}}, h));
    CHECK_FALSE(collision::intersect(ray, Plane{{0, 0, 0}, {0, 0, k_nan}}, h));
    CHECK_FALSE(collision::intersect(ray, Plane{{0, 0, k_inf}, {0, 0, 1}}, h));
    CHECK_FALSE(collision::intersect(ray, Disk{{0, 0, 0}, {0, 0, 1}, 0.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Disk{{0, 0, 0}, {0, 0, 1}, -1.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Disk{{0, 0, 0}, {0, 0, 1}, k_nan}, h));
    CHECK_FALSE(collision::intersect(ray, Disk{{0, 0, 0}, {0, 0, 0}, 1.0f}, h));
    CHECK_FALSE(collision::intersect(ray, Quad{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, h));  // parallel edges
    CHECK_FALSE(collision::intersect(ray, Quad{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}, h));
    CHECK_FALSE(collision::intersect(ray, Quad{{0, 0, 0}, {1, 0, 0}, {0, k_nan, 0}}, h));
    CHECK_FALSE(collision::intersect(ray, Quad{{0, k_inf, 0}, {1, 0, 0}, {0, 1, 0}}, h));
    for (const Ray& bad : {Ray{{0.5f, 0.5f, 3.0f}, {0.0f, 0.0f, 0.0f}}, Ray{{0.5f, 0.5f, 3.0f}, {0.0f, 0.0f, k_nan}},
                           Ray{{0.5f, 0.5f, 3.0f}, {0.0f, 0.0f, -k_inf}}, Ray{{k_nan, 0.5f, 3.0f}, {0.0f, 0.0f, -1.0f}},
                           Ray{{0.5f, 0.5f, k_inf}, {0.0f, 0.0f, -1.0f}}}) {
        CHECK_FALSE(collision::intersect(bad, Plane{{0, 0, 0}, {0, 0, 1}}, h));
        CHECK_FALSE(collision::intersect(bad, Disk{{0, 0, 0}, {0, 0, 1}, 5.0f}, h));
        CHECK_FALSE(collision::intersect(bad, Quad{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, h));
    }
    CHECK(h.t == 3.0f);
}

namespace {

// collision/ray_plane.hpp: |t - t_exact| <= eps |t| + 8 eps_d S / |n.d| with
// S = sum |n_i| |p0_i - o_i| + |t| sum |n_i d_i| (n as used: unit for planes/disks, the
// double cross product for quads; the bound is invariant to n's scale).
reference::ShapeChecks flat_checks(const Ray& ray, const vec3l& p0, const vec3l& n) {
    const vec3l o = widen(ray.origin), d = widen(ray.dir);
    reference::ShapeChecks sc;
    sc.t_bound = [=](const reference::Crossing& x) {
        const vec3l an = glm::abs(n);
        const Real s = glm::dot(an, glm::abs(p0 - o)) + std::fabs(x.t) * glm::dot(an, glm::abs(d));
        return Real(collision::machine_epsilon) * std::fabs(x.t) + 8 * std::ldexp(Real(1), -53) * s / std::fabs(glm::dot(n, d));
    };
    const vec3l un = glm::normalize(n);
    sc.surface_distance = [=](const vec3l& p) { return std::fabs(glm::dot(un, p - p0)); };
    sc.normal_tol = [](const reference::Crossing&, Real) { return Real(gamma(4)); };
    return sc;
}

// The double point's error, ~2^-50 of the coordinates involved: the size a decision made in
// double on that point (rim, edges) can be off by.
Real double_point_error(const Ray& ray, const vec3l& p0, Real extent) {
    const vec3l o = widen(ray.origin), d = widen(ray.dir);
    const Real t = glm::dot(p0 - o, d) / glm::dot(d, d);  // size of t, good enough for a bound
    return std::ldexp(Real(1), -45) * (glm::length(o) + std::fabs(t) * glm::length(d) + glm::length(p0) + extent);
}

void check_plane_case(const Ray& ray, const Plane& p) {
    RayHit hit;
    const bool got = collision::intersect(ray, p, hit);
    const vec3l p0 = widen(p.point), n = widen(p.normal);
    const reference::Crossings ref = reference::plane(widen(ray.origin), widen(ray.dir), p0, n);
    const std::string why = reference::check_answer(ray, got, hit, ref, flat_checks(ray, p0, n));
    INFO(why);
    REQUIRE(why.empty());
}

void check_disk_case(const Ray& ray, const Disk& k) {
    RayHit hit;
    const bool got = collision::intersect(ray, k, hit);
    const vec3l c = widen(k.center), n = widen(k.normal);
    const reference::Crossings ref = reference::disk(widen(ray.origin), widen(ray.dir), c, n, k.radius);
    reference::ShapeChecks sc = flat_checks(ray, c, n);
    sc.margin_tol = double_point_error(ray, c, k.radius);
    const std::string why = reference::check_answer(ray, got, hit, ref, sc);
    INFO(why);
    REQUIRE(why.empty());
}

void check_quad_case(const Ray& ray, const Quad& q) {
    RayHit hit;
    const bool got = collision::intersect(ray, q, hit);
    const vec3l corner = widen(q.corner), eu = widen(q.edge_u), ev = widen(q.edge_v);
    const vec3l n = glm::cross(eu, ev);
    const reference::Crossings ref = reference::quad(widen(ray.origin), widen(ray.dir), corner, eu, ev);
    reference::ShapeChecks sc = flat_checks(ray, corner, n);
    // In (s, t) units: the point's error over the parallelogram's smaller height.
    const Real height = std::min(glm::length(n) / glm::length(eu), glm::length(n) / glm::length(ev));
    sc.margin_tol = double_point_error(ray, corner, glm::length(eu) + glm::length(ev)) / height;
    const std::string why = reference::check_answer(ray, got, hit, ref, sc);
    INFO(why);
    REQUIRE(why.empty());
    if (got && !ref.hits.empty()) {
        REQUIRE(std::fabs(hit.uv.x - ref.hits[0].u) <= Real(gamma(1)) + sc.margin_tol);
        REQUIRE(std::fabs(hit.uv.y - ref.hits[0].v) <= Real(gamma(1)) + sc.margin_tol);
    }
}

}  // namespace

TEST_CASE("flat shapes: random rays agree with the long double reference within the stated bound",
          "[intersect][plane][disk][quad][reference]") {
    std::mt19937_64 rng(0xf1a70001);
    sampling::Sampler sm{rng};
    for (int i = 0; i < 6000; ++i) {
        const float scale = i % 3 == 2 ? 1e5f : 10.0f;  // every third: huge shapes far away
        const glm::vec3 p0 = sm.point(scale);
        const glm::vec3 n = sm.direction();
        const glm::vec3 u = sm.perpendicular(n);
        const float size = scale * sm.log_uniform(1e-3f, 1.0f);
        // Origins near, far (|o| up to 1e5), and grazing (direction 10^-k off the plane).
        glm::vec3 o = i % 3 == 1 ? sm.direction() * sm.log_uniform(1e3f, 1e5f) : p0 + sm.point(2.0f * size);
        const glm::vec3 target = p0 + size * sm.uniform(-1.3f, 1.3f) * u + size * sm.uniform(-1.3f, 1.3f) * glm::cross(n, u);
        Ray ray = sm.ray_towards(o, target);
        if (i % 4 == 3) {
            const glm::vec3 dir = glm::normalize(u + std::pow(10.0f, -sm.uniform(1.0f, 6.0f)) * n);
            ray = Ray{target - dir * size * sm.log_uniform(0.1f, 10.0f), dir * sm.dir_scale()};
        }
        check_plane_case(ray, Plane{p0, n});
        check_disk_case(ray, Disk{p0, n, size});
        check_quad_case(ray, Quad{p0 - 0.5f * size * u, size * u, size * sm.uniform(0.1f, 1.0f) * glm::cross(n, u)});
        check_quad_case(ray, Quad{p0, size * sm.direction(), size * sm.direction()});  // skewed
    }
}

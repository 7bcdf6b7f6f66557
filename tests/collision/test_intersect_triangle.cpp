// Ray-triangle (watertight): unit cases, degenerate input, seeded random rays against the long
// double reference with the bounds stated in collision/triangle_watertight.hpp, and closed
// meshes that no ray may pass through.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <vector>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/mesh.hpp"
#include "collision/triangle_watertight.hpp"
#include "float_specials.hpp"
#include "reference_check.hpp"
#include "reference_intersect.hpp"
#include "reference_mesh.hpp"
#include "reference_sampling.hpp"

using collision::gamma;
using collision::Ray;
using collision::RayHit;
using collision::Triangle;
using reference::Real;
using reference::widen;

namespace {
const Triangle unit_tri{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
}  // namespace

TEST_CASE("triangle: hit with barycentrics, point and unflipped normal", "[intersect][triangle]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{0.25f, 0.5f, 2.0f}, {0.0f, 0.0f, -1.0f}}, unit_tri, h));
    CHECK(h.t == 2.0f);
    CHECK(h.uv == glm::vec2(0.25f, 0.5f));
    CHECK(h.point == glm::vec3(0.25f, 0.5f, 0.0f));
    CHECK(h.normal == glm::vec3(0.0f, 0.0f, 1.0f));
    // From behind: two-sided, the normal stays the geometric one.
    REQUIRE(collision::intersect(Ray{{0.25f, 0.5f, -2.0f}, {0.0f, 0.0f, 4.0f}}, unit_tri, h));
    CHECK(h.t == 0.5f);
    CHECK(h.normal == glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(h.uv == glm::vec2(0.25f, 0.5f));
}

TEST_CASE("triangle: miss, behind, and the tmin/tmax window", "[intersect][triangle]") {
    RayHit h;
    h.t = 9.0f;
    CHECK_FALSE(collision::intersect(Ray{{0.6f, 0.6f, 2.0f}, {0.0f, 0.0f, -1.0f}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, 0.25f, 2.0f}, {0.0f, 0.0f, 1.0f}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, 0.25f, 2.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 2.0f}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, 0.25f, 2.0f}, {0.0f, 0.0f, -1.0f}, 2.0f, 5.0f}, unit_tri, h));
    CHECK(h.t == 9.0f);
    REQUIRE(collision::intersect(collision::segment({0.25f, 0.25f, 1.0f}, {0.25f, 0.25f, -1.0f}), unit_tri, h));
    CHECK(h.t == 0.5f);
}

TEST_CASE("triangle: edges and vertices belong to the triangle", "[intersect][triangle]") {
    RayHit h;
    REQUIRE(collision::intersect(Ray{{0.5f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}}, unit_tri, h));
    CHECK(h.uv == glm::vec2(0.5f, 0.0f));
    REQUIRE(collision::intersect(Ray{{0.5f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}}, unit_tri, h));
    CHECK(h.uv == glm::vec2(0.5f, 0.5f));
    for (const glm::vec3& v : {unit_tri.a, unit_tri.b, unit_tri.c}) {
        REQUIRE(collision::intersect(Ray{v + glm::vec3(0.0f, 0.0f, 1.0f), {0.0f, 0.0f, -1.0f}}, unit_tri, h));
        CHECK(h.point == v);
    }
    CHECK_FALSE(
        collision::intersect(Ray{{collision::next_float_up(0.5f), 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}}, unit_tri, h));
}

TEST_CASE("triangle: rays parallel to the plane miss, also when lying in it", "[intersect][triangle]") {
    RayHit h;
    CHECK_FALSE(collision::intersect(Ray{{-1.0f, 0.25f, 0.0f}, {1.0f, 0.0f, 0.0f}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{-1.0f, 0.25f, 0.5f}, {1.0f, 0.0f, 0.0f}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, 0.25f, 0.0f}, {1.0f, 1.0f, 0.0f}}, unit_tri, h));
}

TEST_CASE("triangle: degenerate input is a miss, never NaN", "[intersect][triangle][degenerate]") {
    const Ray ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    RayHit h;
    h.t = 3.0f;
    CHECK_FALSE(collision::intersect(ray, Triangle{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}, h));  // collinear
    CHECK_FALSE(collision::intersect(ray, Triangle{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}, h));  // coincident
    CHECK_FALSE(collision::intersect(ray, Triangle{{0.25f, 0.25f, 0}, {0.25f, 0.25f, 0}, {0.25f, 0.25f, 0}}, h));
    CHECK_FALSE(collision::intersect(ray, Triangle{{k_nan, 0, 0}, {1, 0, 0}, {0, 1, 0}}, h));
    CHECK_FALSE(collision::intersect(ray, Triangle{{0, 0, 0}, {k_inf, 0, 0}, {0, 1, 0}}, h));
    CHECK_FALSE(collision::intersect(ray, Triangle{{0, 0, 0}, {1, 0, 0}, {0, -k_inf, 0}}, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, 0.0f}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, k_nan}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -k_inf}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{k_nan, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, k_inf, 1.0f}, {0.0f, 0.0f, -1.0f}}, unit_tri, h));
    CHECK_FALSE(collision::intersect(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}, k_nan, k_inf}, unit_tri, h));
    CHECK(h.t == 3.0f);
}

namespace {

// The stated bound of collision/triangle_watertight.hpp, evaluated with exact sheared values;
// also the exact edge functions, whose distance from 0 decides hit/miss.
struct ShearBound {
    Real d_t = 0, d_det = 0, det = 0, d_e = 0, min_abs_e = 0;
    Real t_bound(Real t) const {
        const Real denom = std::fabs(det) - d_det;
        return denom > 0 ? (d_t + std::fabs(t) * d_det) / denom : std::numeric_limits<Real>::infinity();
    }
};

ShearBound shear_bound(const Ray& ray, const Triangle& tri) {
    const collision::TriangleRay tr = collision::prepare_triangle_ray(ray);
    const auto o = widen(ray.origin), d = widen(ray.dir);
    const Real sx = -d[tr.kx] / d[tr.kz], sy = -d[tr.ky] / d[tr.kz];
    Real xt[3], yt[3], z[3], zt[3];
    const glm::vec3* v[3] = {&tri.a, &tri.b, &tri.c};
    for (int i = 0; i < 3; ++i) {
        const auto p = widen(*v[i]) - o;
        xt[i] = p[tr.kx] + sx * p[tr.kz];
        yt[i] = p[tr.ky] + sy * p[tr.kz];
        z[i] = p[tr.kz];
        zt[i] = p[tr.kz] / d[tr.kz];
    }
    const Real e[3] = {xt[1] * yt[2] - yt[1] * xt[2], xt[2] * yt[0] - yt[2] * xt[0], xt[0] * yt[1] - yt[0] * xt[1]};
    const auto max_abs = [](const Real* a) { return std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])}); };
    const Real mx = max_abs(xt), my = max_abs(yt), mz = max_abs(z), mzt = max_abs(zt), me = max_abs(e);
    const Real dx = Real(gamma(5)) * (mx + mz), dy = Real(gamma(5)) * (my + mz), dz = Real(gamma(3)) * mzt;
    ShearBound b;
    b.d_e = 2 * (Real(gamma(2)) * mx * my + dy * mx + dx * my);
    b.d_t = 3 * (Real(gamma(3)) * me * mzt + b.d_e * mzt + dz * me);
    b.d_det = 3 * b.d_e + Real(gamma(4)) * (std::fabs(e[0]) + std::fabs(e[1]) + std::fabs(e[2]));
    b.det = e[0] + e[1] + e[2];
    b.min_abs_e = std::min({std::fabs(e[0]), std::fabs(e[1]), std::fabs(e[2])});
    return b;
}

// Distance of p from the triangle's plane, exactly.
Real plane_distance(const Triangle& tri, const reference::vec3l& p) {
    const auto a = widen(tri.a);
    const auto n = glm::normalize(glm::cross(widen(tri.b) - a, widen(tri.c) - a));
    return std::fabs(glm::dot(n, p - a));
}

void check_triangle_case(const Ray& ray, const Triangle& tri) {
    RayHit hit;
    const bool got = collision::intersect(ray, tri, hit);
    const auto o = widen(ray.origin), d = widen(ray.dir);
    reference::Crossings ref = reference::triangle(o, d, widen(tri.a), widen(tri.b), widen(tri.c));
    const ShearBound sb = shear_bound(ray, tri);
    // Hit/miss is decided by the signs of the float edge functions, each within d_e of exact.
    ref.margin = sb.min_abs_e;
    const auto bound = [&](const reference::Crossing& x) { return sb.t_bound(x.t); };
    const reference::Verdict v = reference::judge(got, hit, ref, ray.tmin, ray.tmax, bound, sb.d_e);
    INFO(v.why);
    REQUIRE(v.ok);
    if (!got) return;
    // Point: on the plane within its per-axis bound; barycentrics within the bound's reach.
    REQUIRE(plane_distance(tri, widen(hit.point)) <= glm::length(widen(hit.point_error)));
    const float b0 = 1.0f - hit.uv.x - hit.uv.y;
    REQUIRE(hit.uv.x >= 0.0f);
    REQUIRE(hit.uv.y >= 0.0f);
    REQUIRE(b0 >= -4 * collision::machine_epsilon);
    if (v.matched != nullptr) {
        const auto exact_n = v.matched->normal;
        const auto e1 = widen(tri.b) - widen(tri.a), e2 = widen(tri.c) - widen(tri.a);
        const Real sine_inv = glm::length(e1) * glm::length(e2) / glm::length(glm::cross(e1, e2));
        REQUIRE(glm::length(widen(hit.normal) - exact_n) <= 6 * Real(gamma(4)) * sine_inv + Real(gamma(6)));
    }
}

}  // namespace

TEST_CASE("triangle: random rays agree with the long double reference within the stated bound",
          "[intersect][triangle][reference]") {
    std::mt19937_64 rng(0x7a1e0001);
    sampling::Sampler sm{rng};
    const auto random_triangle = [&](const glm::vec3& center, float size) {
        return Triangle{center + sm.point(size), center + sm.point(size), center + sm.point(size)};
    };
    const auto towards = [&](const Triangle& t) {  // a point on or near the triangle
        const float u = sm.uniform(-0.2f, 1.2f), v = sm.uniform(-0.2f, 1.2f - u);
        return t.a + u * (t.b - t.a) + v * (t.c - t.a);
    };
    for (int i = 0; i < 10000; ++i) {
        const Triangle t = random_triangle(sm.point(10.0f), sm.log_uniform(0.01f, 10.0f));
        check_triangle_case(sm.ray_towards(t.a + sm.point(20.0f), towards(t)), t);
        // Far origins.
        const Triangle t2 = random_triangle(sm.point(10.0f), sm.log_uniform(0.1f, 10.0f));
        check_triangle_case(sm.ray_towards(sm.direction() * sm.log_uniform(1e3f, 1e5f), towards(t2)), t2);
        // Huge triangles, far from the origin of coordinates.
        const Triangle t3 = random_triangle(sm.point(1e5f), 1e5f);
        check_triangle_case(sm.ray_towards(t3.a + sm.point(1e5f), towards(t3)), t3);
        // Grazing: the direction makes an angle of 10^-k (k up to 5) with the plane.
        const Triangle t4 = random_triangle(sm.point(10.0f), sm.log_uniform(0.1f, 10.0f));
        const glm::vec3 n = glm::normalize(glm::cross(t4.b - t4.a, t4.c - t4.a));
        const glm::vec3 in_plane = sm.perpendicular(n);
        const float angle = std::pow(10.0f, -sm.uniform(1.0f, 5.0f));
        const glm::vec3 dir = glm::normalize(in_plane + angle * n);
        const glm::vec3 target = towards(t4);
        const float back = sm.log_uniform(0.1f, 100.0f);
        check_triangle_case(Ray{target - dir * back, dir * sm.dir_scale()}, t4);
    }
}

namespace {

// Every ray from inside a closed mesh must leave through some triangle; every line that enters
// it from outside must hit some triangle. Counts the rays that found no triangle.
int count_leaks(const collision::TriangleMesh& mesh, const glm::vec3& inside,
                const std::vector<glm::vec3>& targets) {
    int leaks = 0;
    for (const glm::vec3& target : targets) {
        for (int from_outside = 0; from_outside < 2; ++from_outside) {
            Ray ray{inside, target - inside};
            if (from_outside) ray = Ray{target + 3.0f * (target - inside), inside - target};
            bool any = false;
            RayHit h;
            for (std::size_t i = 0; i < mesh.triangle_count() && !any; ++i)
                any = collision::intersect(ray, mesh.triangle(i), h);
            leaks += any ? 0 : 1;
        }
    }
    return leaks;
}

}  // namespace

TEST_CASE("triangle: rays through shared edges and vertices of closed meshes never leak",
          "[intersect][triangle][watertight]") {
    std::mt19937_64 rng(0x7a1e0002);
    sampling::Sampler sm{rng};
    // An octahedron on the axes: axis-parallel rays through its vertices and edge midpoints are
    // the classic leak of non-watertight tests (several triangles meet exactly there).
    const collision::TriangleMesh octa = meshes::octahedron({0.0f, 0.0f, 0.0f}, 1.0f);
    std::vector<glm::vec3> targets = meshes::vertex_and_edge_targets(octa, sm, 4);
    CHECK(count_leaks(octa, {0.0f, 0.0f, 0.0f}, targets) == 0);
    // An icosphere off the origin with awkward scale: float rounding everywhere.
    const glm::vec3 center(0.3f, -1.7f, 2.1f);
    const collision::TriangleMesh ico = meshes::icosphere(center, 3.7f, 2);
    targets = meshes::vertex_and_edge_targets(ico, sm, 4);
    REQUIRE(targets.size() > 1000);
    CHECK(count_leaks(ico, center, targets) == 0);
    // Far from the origin: every coordinate carries rounding of ~1e-2.
    const glm::vec3 far(1.1e5f, -0.7e5f, 0.3e5f);
    const collision::TriangleMesh far_ico = meshes::icosphere(far, 5.0f, 1);
    CHECK(count_leaks(far_ico, far + glm::vec3(0.01f, 0.02f, -0.03f), meshes::vertex_and_edge_targets(far_ico, sm, 4)) ==
          0);
}

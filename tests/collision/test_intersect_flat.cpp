// Ray-plane, ray-disk, ray-quad: unit cases (parallel rays, rims and edges), degenerate input,
// seeded random rays against the long double reference with the bounds stated in
// collision/detail/ray_plane.hpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/surface_uv.hpp"
#include "collision/triangle_watertight.hpp"
#include "float_specials.hpp"
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
    CHECK(collision::surface_uv(lid, h).x == 0.5f);
    REQUIRE(collision::intersect(Ray{{0.0f, 5.0f, 2.0f}, {0.0f, -1.0f, 0.0f}}, lid, h));  // on the rim
    CHECK(collision::surface_uv(lid, h).x == 1.0f);
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

// collision/detail/ray_plane.hpp: |t - t_exact| <= eps |t| + 8 eps_d S / |n.d| with
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

// The hit/miss margin of collision/intersect_quad.cpp: the exact edge functions of the exact
// vertices in the ray's sheared frame (their smallest |e_i| is the reference margin) and the
// stated tolerance de + 4 R (max|xt| + max|yt|) + 4 R^2, R = gamma(2) max |v_i|.
struct QuadMargin {
    Real min_abs_e = 0, tol = 0;
};

QuadMargin quad_margin(const Ray& ray, const Quad& q) {
    const collision::TriangleRay tr = collision::prepare_triangle_ray(ray);
    const vec3l o = widen(ray.origin), d = widen(ray.dir);
    const Real sx = -d[tr.kx] / d[tr.kz], sy = -d[tr.ky] / d[tr.kz];
    const vec3l c = widen(q.corner), eu = widen(q.edge_u), ev = widen(q.edge_v);
    const vec3l v[4] = {c, c + eu, c + eu + ev, c + ev};
    Real xt[4], yt[4], mx = 0, my = 0, mz = 0, mv = 0;
    for (int i = 0; i < 4; ++i) {
        const vec3l p = v[i] - o;
        xt[i] = p[tr.kx] + sx * p[tr.kz];
        yt[i] = p[tr.ky] + sy * p[tr.kz];
        mx = std::max(mx, std::fabs(xt[i]));
        my = std::max(my, std::fabs(yt[i]));
        mz = std::max(mz, std::fabs(p[tr.kz]));
        mv = std::max({mv, std::fabs(v[i].x), std::fabs(v[i].y), std::fabs(v[i].z)});
    }
    QuadMargin m;
    m.min_abs_e = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        m.min_abs_e = std::min(m.min_abs_e, std::fabs(xt[i] * yt[j] - yt[i] * xt[j]));
    }
    const Real dx = Real(gamma(5)) * (mx + mz), dy = Real(gamma(5)) * (my + mz);
    const Real de = 2 * (Real(gamma(2)) * mx * my + dy * mx + dx * my);
    const Real r = Real(gamma(2)) * mv;
    m.tol = de + 4 * r * (mx + my) + 4 * r * r;
    return m;
}

void check_quad_case(const Ray& ray, const Quad& q) {
    RayHit hit;
    const bool got = collision::intersect(ray, q, hit);
    const vec3l corner = widen(q.corner), eu = widen(q.edge_u), ev = widen(q.edge_v);
    const vec3l n = glm::cross(eu, ev);
    reference::Crossings ref = reference::quad(widen(ray.origin), widen(ray.dir), corner, eu, ev);
    // uv comes from the double plane point: its error in (s, t) units is the point's error over
    // the parallelogram's smaller height.
    const Real height = std::min(glm::length(n) / glm::length(eu), glm::length(n) / glm::length(ev));
    const Real uv_tol = double_point_error(ray, corner, glm::length(eu) + glm::length(ev)) / height;
    reference::ShapeChecks sc = flat_checks(ray, corner, n);
    // Hit/miss is decided by the sheared edge functions (see quad_margin).
    const QuadMargin qm = quad_margin(ray, q);
    ref.margin = qm.min_abs_e;
    sc.margin_tol = qm.tol;
    const std::string why = reference::check_answer(ray, got, hit, ref, sc);
    INFO(why);
    REQUIRE(why.empty());
    if (got && !ref.hits.empty()) {
        REQUIRE(std::fabs(hit.uv.x - ref.hits[0].u) <= Real(gamma(1)) + uv_tol);
        REQUIRE(std::fabs(hit.uv.y - ref.hits[0].v) <= Real(gamma(1)) + uv_tol);
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

namespace {

// A closed cube [lo, lo + size] whose faces are Quads (edge_u x edge_v outward) or, where
// `split` says so, the two triangles (v0, v1, v2), (v0, v2, v3) of that quad's float vertices.
// Every vertex coordinate is lo_i or lo_i + size_i, bit-identical in every face.
struct MixedCube {
    std::vector<Quad> quads;
    std::vector<collision::Triangle> triangles;
};

MixedCube mixed_cube(const glm::vec3& lo, float size, unsigned split) {
    const glm::vec3 x(size, 0, 0), y(0, size, 0), z(0, 0, size);
    const Quad faces[6] = {{lo, z, y}, {lo + x, y, z}, {lo, x, z}, {lo + y, z, x}, {lo, y, x}, {lo + z, x, y}};
    MixedCube cube;
    for (int f = 0; f < 6; ++f) {
        const Quad& q = faces[f];
        if (!(split >> f & 1u)) {
            cube.quads.push_back(q);
            continue;
        }
        const glm::vec3 v1 = q.corner + q.edge_u, v2 = v1 + q.edge_v, v3 = q.corner + q.edge_v;
        cube.triangles.push_back({q.corner, v1, v2});
        cube.triangles.push_back({q.corner, v2, v3});
    }
    return cube;
}

bool hits_cube(const MixedCube& cube, const Ray& ray) {
    RayHit h;
    for (const Quad& q : cube.quads)
        if (collision::intersect(ray, q, h)) return true;
    for (const collision::Triangle& t : cube.triangles)
        if (collision::intersect(ray, t, h)) return true;
    return false;
}

}  // namespace

TEST_CASE("quad: closed cubes of quads, and of quads and triangles, never leak at shared edges and corners",
          "[intersect][quad][watertight]") {
    std::mt19937_64 rng(0xf1a70002);
    sampling::Sampler sm{rng};
    int rays = 0, leaks = 0;
    for (int i = 0; i < 400; ++i) {
        const float size = sm.log_uniform(1e-2f, 1e3f);
        const glm::vec3 lo = i % 4 == 0 ? glm::vec3(-0.5f * size) : sm.point(1e3f);
        // Half the cubes all quads, the others a random mix (at least one face split).
        const unsigned split = i % 2 == 0 ? 0u : 1u + unsigned(sm.uniform(0.0f, 62.99f));
        const MixedCube cube = mixed_cube(lo, size, split);
        const glm::vec3 hi = lo + glm::vec3(size), centre = lo + 0.5f * glm::vec3(size);
        for (int k = 0; k < 32; ++k) {
            // Targets: a corner, or a point of an edge (its midpoint or anywhere on it).
            glm::vec3 target(sm.uniform(0, 1) < 0.5f ? lo.x : hi.x, sm.uniform(0, 1) < 0.5f ? lo.y : hi.y,
                             sm.uniform(0, 1) < 0.5f ? lo.z : hi.z);
            if (k % 2 == 1) {
                const int axis = k / 2 % 3;
                target[axis] = lo[axis] + (k % 4 == 1 ? 0.5f : sm.uniform(0.0f, 1.0f)) * size;
            }
            const glm::vec3 inside = k % 3 == 0 ? centre : centre + 0.3f * size * sm.direction();
            // From inside out, and from outside in along the same line.
            const Ray out{inside, target - inside};
            const Ray in{target + (target - inside), inside - target};
            rays += 2;
            leaks += !hits_cube(cube, out);
            leaks += !hits_cube(cube, in);
        }
    }
    INFO("leaks " << leaks << " of " << rays);
    CHECK(leaks == 0);
}

// The point error bounds in use: a ray leaving a hit point, its origin pushed off the surface by
// dot(|n|, point_error) along the normal (pbrt-v4's offset, as raytracer/geometry/spawn_ray.cpp
// does), must not hit the surface it leaves. For the convex shapes: leaving outward finds no
// hit at all, leaving inward finds the far side, not the surface just left. The thesis variants
// have no error bound (point_error = 0), so their spawned rays re-hit ("acne"): counted.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/thesis/intersect.hpp"
#include "reference_sampling.hpp"

using collision::Ray;
using collision::RayHit;

namespace {

glm::vec3 offset_origin(const RayHit& hit, const glm::vec3& dir) {
    const float d = glm::dot(glm::abs(hit.normal), hit.point_error);
    glm::vec3 offset = d * hit.normal;
    if (glm::dot(dir, hit.normal) < 0.0f) offset = -offset;
    glm::vec3 po = hit.point + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) po[i] = collision::next_float_up(po[i]);
        else if (offset[i] < 0.0f) po[i] = collision::next_float_down(po[i]);
    }
    return po;
}

// A direction in the hemisphere around n (or -n), never grazing closer than 1e-3 rad.
glm::vec3 hemisphere(sampling::Sampler& sm, const glm::vec3& n, float side) {
    for (;;) {
        const glm::vec3 v = sm.direction();
        const float c = side * glm::dot(v, n);
        if (c > 1e-3f) return v;
        if (c < -1e-3f) return -v;
    }
}

struct SpawnTally {
    int primaries = 0, outward_rehits = 0, inward_wrong = 0;
    std::string first_failure;
};

// `intersect` is the routine under test; `closed` says whether the shape has an inside (then
// an inward ray must meet the far side at a clear distance, more than the offset box).
template <typename Shape, typename Intersect>
void spawn_from(const Ray& primary, const Shape& shape, float size, bool closed, sampling::Sampler& sm,
                Intersect intersect, SpawnTally& tally) {
    RayHit hit;
    if (!intersect(primary, shape, hit)) return;
    ++tally.primaries;
    for (int k = 0; k < 4; ++k) {
        // Flat shapes are two-sided: both sides count as "outward".
        const float side = k % 2 == 0 || !closed ? (k % 2 == 0 ? 1.0f : -1.0f) : -1.0f;
        const glm::vec3 dir = hemisphere(sm, hit.normal, side) * sm.dir_scale();
        const Ray spawned{offset_origin(hit, dir), dir};
        RayHit again;
        const bool got = intersect(spawned, shape, again);
        if (side > 0.0f || !closed) {
            tally.outward_rehits += got;
        } else if (size > 1e3f * glm::length(hit.point_error)) {
            // (A shape within a few rounding errors of its own size, e.g. r = 1e-2 at 1e5 where
            // floats are 8e-3 apart, can be stepped over entirely by the offset: not checked.)
            // Leaving a convex shape: the exit normal faces along the ray. Re-hitting the
            // entry surface would give the entry normal, which faces against it (the
            // directions are at least 1e-3 rad off the tangent plane).
            const bool wrong = !got || glm::dot(again.normal, glm::normalize(dir)) < -1e-4f;
            if (wrong && tally.first_failure.empty()) {
                std::ostringstream m;
                m << "first inward failure: got " << got << " t " << again.t << " |dir| " << glm::length(dir)
                  << " n.dir " << glm::dot(again.normal, glm::normalize(dir)) << " entry n.dir "
                  << glm::dot(hit.normal, glm::normalize(dir)) << " point " << hit.point.x << "," << hit.point.y << ","
                  << hit.point.z << " err " << glm::length(hit.point_error);
                tally.first_failure = m.str();
            }
            tally.inward_wrong += wrong;
        }
    }
}

const auto robust = [](const Ray& r, const auto& s, RayHit& h) { return collision::intersect(r, s, h); };
const auto thesis_intersect = [](const Ray& r, const auto& s, RayHit& h) { return collision::thesis::intersect(r, s, h); };

template <typename Make, typename Intersect>
SpawnTally run_spawn(std::uint64_t seed, bool closed, Make make, Intersect intersect) {
    std::mt19937_64 rng(seed);
    sampling::Sampler sm{rng};
    SpawnTally tally;
    for (int i = 0; i < 3000; ++i) {
        const auto [shape, target, scale] = make(sm, i);
        const Ray primary{target + sm.direction() * (scale * sm.log_uniform(1.5f, 1e3f)), glm::vec3(0.0f)};
        const Ray aimed{primary.origin, (target - primary.origin) * sm.dir_scale() / glm::length(target - primary.origin)};
        spawn_from(aimed, shape, scale, closed, sm, intersect, tally);
    }
    return tally;
}

// Positions from near the origin to 1e5 away, sizes from 1e-2 to 1e5. Each maker returns the
// shape, a point inside it (or on it) to aim at, and its thickness (smallest dimension).
float position_scale(int i) { return i % 3 == 0 ? 10.0f : (i % 3 == 1 ? 1e4f : 1e5f); }

auto make_sphere = [](sampling::Sampler& sm, int i) {
    const collision::Sphere s{sm.point(position_scale(i)), sm.log_uniform(1e-2f, 1e5f)};
    return std::tuple{s, s.center + sm.direction() * (0.9f * s.radius), s.radius};
};
auto make_ellipsoid = [](sampling::Sampler& sm, int i) {
    const collision::Ellipsoid e{sm.point(position_scale(i)),
                                 glm::vec3(sm.log_uniform(1e-1f, 1e3f), sm.log_uniform(1e-1f, 1e3f), sm.log_uniform(1e-1f, 1e3f))};
    return std::tuple{e, e.center + 0.5f * e.radii * sm.point(1.0f), std::min({e.radii.x, e.radii.y, e.radii.z})};
};
auto make_capsule = [](sampling::Sampler& sm, int i) {
    const glm::vec3 a = sm.point(position_scale(i));
    const float r = sm.log_uniform(1e-2f, 1e3f);
    const collision::OrientedCapsule c{a, a + sm.direction() * sm.log_uniform(1e-2f, 1e3f), r};
    return std::tuple{c, 0.5f * (c.a + c.b) + sm.direction() * (0.5f * r), r};
};
auto make_cylinder = [](sampling::Sampler& sm, int i) {
    const collision::Cylinder c{sm.point(position_scale(i)), sm.log_uniform(1e-2f, 1e3f), sm.log_uniform(1e-2f, 1e3f)};
    return std::tuple{c, c.center + 0.45f * glm::vec3(c.radius, c.height, c.radius) * sm.point(1.0f),
                      std::min(c.radius, c.height)};
};
auto make_box = [](sampling::Sampler& sm, int i) {
    const collision::Aabb b{sm.point(position_scale(i)),
                            glm::vec3(sm.log_uniform(1e-2f, 1e3f), sm.log_uniform(1e-2f, 1e3f), sm.log_uniform(1e-2f, 1e3f))};
    return std::tuple{b, b.center + 0.45f * b.size * sm.point(1.0f), std::min({b.size.x, b.size.y, b.size.z})};
};
auto make_triangle = [](sampling::Sampler& sm, int i) {
    const glm::vec3 c = sm.point(position_scale(i));
    const float size = sm.log_uniform(1e-2f, 1e3f);
    const collision::Triangle t{c + sm.point(size), c + sm.point(size), c + sm.point(size)};
    const float u = sm.uniform(0.05f, 0.9f), v = sm.uniform(0.05f, 0.95f - u);
    return std::tuple{t, t.a + u * (t.b - t.a) + v * (t.c - t.a), size};
};
auto make_disk = [](sampling::Sampler& sm, int i) {
    const collision::Disk d{sm.point(position_scale(i)), sm.direction(), sm.log_uniform(1e-2f, 1e3f)};
    return std::tuple{d, d.center + sm.perpendicular(d.normal) * (0.9f * d.radius * sm.uniform(0.0f, 1.0f)), d.radius};
};
auto make_quad = [](sampling::Sampler& sm, int i) {
    const float size = sm.log_uniform(1e-2f, 1e3f);
    const collision::Quad q{sm.point(position_scale(i)), sm.direction() * size, sm.direction() * size};
    return std::tuple{q, q.corner + sm.uniform(0.05f, 0.95f) * q.edge_u + sm.uniform(0.05f, 0.95f) * q.edge_v, size};
};

void require_clean(const SpawnTally& t) {
    INFO(t.primaries << " primary hits, " << t.outward_rehits << " outward re-hits, " << t.inward_wrong
                     << " inward rays not reaching the far side; " << t.first_failure);
    REQUIRE(t.primaries > 1000);
    CHECK(t.outward_rehits == 0);
    CHECK(t.inward_wrong == 0);
}

}  // namespace

TEST_CASE("spawned rays never re-hit the surface they leave (curved shapes)", "[intersect][spawn]") {
    require_clean(run_spawn(0x5a3e0001, true, make_sphere, robust));
    require_clean(run_spawn(0x5a3e0002, true, make_ellipsoid, robust));
    require_clean(run_spawn(0x5a3e0003, true, make_capsule, robust));
    require_clean(run_spawn(0x5a3e0004, true, make_cylinder, robust));
}

TEST_CASE("spawned rays never re-hit the surface they leave (box and flat shapes)", "[intersect][spawn]") {
    require_clean(run_spawn(0x5a3e0005, true, make_box, robust));
    require_clean(run_spawn(0x5a3e0006, false, make_triangle, robust));
    require_clean(run_spawn(0x5a3e0007, false, make_disk, robust));
    require_clean(run_spawn(0x5a3e0008, false, make_quad, robust));
}

TEST_CASE("thesis variants: spawned rays re-hit the surface they leave (no error bound to offset by)",
          "[intersect][spawn][thesis]") {
    const SpawnTally sphere = run_spawn(0x5a3e0001, true, make_sphere, thesis_intersect);
    const SpawnTally triangle = run_spawn(0x5a3e0006, false, make_triangle, thesis_intersect);
    INFO("sphere: " << sphere.outward_rehits << " outward re-hits, " << sphere.inward_wrong << " inward wrong of "
                    << sphere.primaries << "; triangle: " << triangle.outward_rehits << " re-hits of "
                    << triangle.primaries);
    CHECK(sphere.outward_rehits + sphere.inward_wrong > sphere.primaries / 20);
    CHECK(triangle.outward_rehits > triangle.primaries / 20);
}

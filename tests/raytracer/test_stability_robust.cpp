// Cross-cutting stability of the robust intersectors (and where Embree's default test breaks):
// leaks through closed meshes at shared edges and vertices, self-hits of secondary rays across
// scales 1e-4 .. 1e5 (pbrt's re-intersection test), t within the stated bound far and huge.
// Per-routine tests live in tests/collision; these run the accuracy harness's families.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "raytracer/accuracy/reference.hpp"
#include "raytracer/accuracy/routines.hpp"
#include "raytracer/accuracy/run.hpp"

using namespace sweeptrace::accuracy;

namespace {

template <class S>
Metrics robust(Family f, std::size_t n, std::uint64_t seed) {
    return run_family(variant_of<S>("robust", &collision::intersect), f, n, seed);
}

}  // namespace

TEST_CASE("stability: the watertight triangle test never leaks through a closed icosphere at its edges and "
          "vertices",
          "[stability]") {
    const auto meshes = make_closed_meshes<collision::Triangle>(20000, 11);
    const Metrics m = run_closed_meshes(variant_of<collision::Triangle>("robust", &collision::intersect), meshes);
    INFO("rays " << m.rays);
    CHECK(m.rays >= 20000);
    CHECK(m.leaks == 0);
}

TEST_CASE("stability: secondary rays of the robust sphere and triangle never re-hit their surface, scales 1e-4 .. "
          "1e5",
          "[stability]") {
    for (Family f : {Family::SurfaceOut, Family::SurfaceIn}) {
        const Metrics m = robust<collision::Sphere>(f, 20000, 5);
        INFO("sphere " << family_name(f) << ": " << m.rays << " secondary rays");
        CHECK(m.rays > 15000);
        CHECK(m.self_hits == 0);
    }
    for (Family f : {Family::SurfaceOut, Family::SurfaceIn}) {
        const Metrics m = robust<collision::Triangle>(f, 20000, 5);
        INFO("triangle " << family_name(f) << ": " << m.rays << " secondary rays");
        CHECK(m.rays > 4000);
        CHECK(m.self_hits == 0);
    }
}

TEST_CASE("stability: robust sphere t stays within its stated bound for origins up to 1e6 away and radius 1e5",
          "[stability]") {
    // collision/intersect_sphere.cpp states
    //   |t - t_exact| <= gamma(32) ((|f| + r)(1 + r / h) / |d| + |t|),  h = sqrt(r^2 - |l|^2),
    // with f = o - c and l the closest approach; h is taken from the long double reference.
    for (Family f : {Family::Far, Family::Huge}) {
        std::size_t scored = 0;
        for (const auto& c : make_cases<collision::Sphere>(f, 20000, 9)) {
            const RefHit ref = reference(c.ray, c.shape);
            collision::RayHit h;
            const bool hit = collision::intersect(c.ray, c.shape, h);
            if (ref.outcome != RefOutcome::Hit || !hit) continue;
            const LVec3 fo = widen(c.ray.origin) - widen(c.shape.center), d = widen(c.ray.dir);
            const LVec3 l = fo - (glm::dot(fo, d) / glm::dot(d, d)) * d;
            const long double r = c.shape.radius;
            const long double half_chord = std::sqrt(std::max(0.0L, r * r - glm::dot(l, l)));
            const long double bound = collision::gamma(32) * ((std::sqrt(glm::dot(fo, fo)) + r) * (1.0L + r / half_chord) /
                                                                  std::sqrt(glm::dot(d, d)) +
                                                              std::fabs(static_cast<long double>(h.t)));
            INFO(family_name(f) << " t " << h.t << " reference " << static_cast<double>(ref.t));
            CHECK(std::fabs(h.t - ref.t) <= bound);
            ++scored;
        }
        CHECK(scored > 10000);
    }
}

TEST_CASE("stability: Embree's default triangle test leaks at shared edges and vertices, RTC_SCENE_FLAG_ROBUST "
          "far less (the watertight test: none, above)",
          "[stability][embree]") {
    // Rays from inside a closed icosphere aimed exactly at its vertices (and within rounding at
    // its edges). Embree's default test is not watertight: `sweeptrace accuracy --rays 20000`
    // measured 777 of 20,224 rays (3.8%) escaping. RTC_SCENE_FLAG_ROBUST closes most gaps but
    // not all: `sweeptrace accuracy --meshes` finds a few per ten thousand at vertices of
    // icospheres and of spot (see docs/RESULTS.md). The watertight test lets none through.
    const auto meshes = make_closed_meshes<collision::Triangle>(10000, 11);
    const Metrics fast = run_closed_meshes(embree_triangle_variant(false), meshes);
    const Metrics robust = run_closed_meshes(embree_triangle_variant(true), meshes);
    INFO("rays " << fast.rays << ": Embree default leaks " << fast.leaks << ", robust flag " << robust.leaks);
    CHECK(fast.leaks > fast.rays / 100);
    CHECK(robust.leaks * 10 < fast.leaks);
}

namespace {

// Every family of one shape for its robust routine: no answer may be wrong beyond rounding
// (reference.hpp: a case still decided with float_band is one a routine within its stated
// bound must get right).
template <class S>
void check_no_wrong_beyond_rounding() {
    for (Family f : all_families) {
        if (!family_applies<S>(f)) continue;
        const Metrics m = robust<S>(f, 3000, 17);
        INFO(shape_name<S>() << " " << family_name(f) << ": " << m.wrong << " wrong of " << m.rays << ", "
                             << m.within_rounding << " within rounding");
        CHECK(m.wrong_clear == 0);
    }
}

}  // namespace

TEST_CASE("stability: robust routines are never wrong beyond rounding, in any family", "[stability]") {
    check_no_wrong_beyond_rounding<collision::Sphere>();
    check_no_wrong_beyond_rounding<collision::Aabb>();
    check_no_wrong_beyond_rounding<collision::Cylinder>();
    check_no_wrong_beyond_rounding<collision::Capsule>();
    check_no_wrong_beyond_rounding<collision::OrientedCapsule>();
    check_no_wrong_beyond_rounding<collision::Ellipsoid>();
    check_no_wrong_beyond_rounding<collision::Plane>();
    check_no_wrong_beyond_rounding<collision::Disk>();
    check_no_wrong_beyond_rounding<collision::Quad>();
    check_no_wrong_beyond_rounding<collision::Triangle>();
}

TEST_CASE("stability: robust box and cylinder never let a ray from inside out through an edge or rim",
          "[stability]") {
    CHECK(robust<collision::Aabb>(Family::Edges, 20000, 23).leaks == 0);
    CHECK(robust<collision::Cylinder>(Family::Edges, 20000, 23).leaks == 0);
}

// A closed cube of six collision::Quad faces with bit-identical corners: the quad test decides
// with the same sheared edge functions as the watertight triangle test, so no ray aimed at the
// cube's corners and edges escapes (it leaked 158 of 20,224 while each quad decided on its own
// plane point).
TEST_CASE("stability: robust quads never leak through a closed cube at its edges and corners", "[stability]") {
    const auto cubes = make_closed_meshes<collision::Quad>(10000, 11);
    const Metrics m = run_closed_meshes(variant_of<collision::Quad>("robust", &collision::intersect), cubes);
    INFO("leaks " << m.leaks << " of " << m.rays);
    CHECK(m.leaks == 0);
}

// Where the thesis-faithful ray tests (collision/thesis/) break, and by how much, measured by the
// accuracy harness on the same families as the robust routines (which pass every one of these:
// test_stability_robust.cpp). Each figure in a comment is from
//   sweeptrace accuracy --rays 20000        (seed 1)
// and each test asserts a clearly smaller threshold on 4,000 rays of another seed, so it holds
// however the seed falls but fails if the weakness disappears (then the comment is stale).
#include <catch2/catch.hpp>

#include "collision/intersect.hpp"
#include "collision/thesis/intersect.hpp"
#include "raytracer/accuracy/run.hpp"

using namespace sweeptrace::accuracy;

namespace {

template <class S>
Metrics thesis(Family f, std::size_t n = 4000) {
    return run_family(variant_of<S>("thesis", &collision::thesis::intersect), f, n, 29);
}

template <class S>
Metrics robust(Family f, std::size_t n = 4000) {
    return run_family(variant_of<S>("robust", &collision::intersect), f, n, 29);
}

double rate(std::size_t count, std::size_t of) { return of ? double(count) / double(of) : 0.0; }

}  // namespace

TEST_CASE("thesis sphere: the textbook quadratic cancels for far origins and tiny spheres", "[stability][thesis]") {
    // c = p.p + q.q - 2 p.q - r^2 loses everything when |p - q| >> r: measured 1,381 of 20,000
    // far rays (7%) and 7,732 of 20,000 tiny-sphere rays (39%) wrong beyond rounding, t error
    // p99 4.6e-4; the robust sphere: none wrong, p99 2.4e-7.
    const Metrics far = thesis<collision::Sphere>(Family::Far);
    const Metrics tiny = thesis<collision::Sphere>(Family::Tiny);
    INFO("far: " << far.wrong_clear << " wrong beyond rounding, t p99 " << far.t_p99 << "; tiny: " << tiny.wrong_clear);
    CHECK(rate(far.wrong_clear, far.rays) > 0.02);
    CHECK(far.t_p99 > 100.0 * robust<collision::Sphere>(Family::Far).t_p99);
    CHECK(rate(tiny.wrong_clear, tiny.rays) > 0.15);
}

TEST_CASE("thesis ellipsoid: scaling to the unit sphere then the textbook quadratic fails on huge ellipsoids",
          "[stability][thesis]") {
    // Measured: 6,936 of 20,000 rays at radius 1e5 wrong beyond rounding (35%), median t error 1.3.
    const Metrics huge = thesis<collision::Ellipsoid>(Family::Huge);
    INFO(huge.wrong_clear << " of " << huge.rays << " wrong beyond rounding, t median " << huge.t_median);
    CHECK(rate(huge.wrong_clear, huge.rays) > 0.1);
    CHECK(robust<collision::Ellipsoid>(Family::Huge).wrong_clear == 0);
}

TEST_CASE("thesis triangle: plane + barycentric leaks through a closed mesh at shared edges and vertices",
          "[stability][thesis]") {
    // Measured: 1,173 of 20,224 rays from inside an icosphere (5.8%) escape; watertight: none.
    const Metrics edges = thesis<collision::Triangle>(Family::Edges);
    INFO(edges.leaks << " leaks of " << edges.rays);
    CHECK(rate(edges.leaks, edges.rays) > 0.01);
}

TEST_CASE("thesis cylinder: skipping the side for origins inside the infinite cylinder lets rays out at the rim",
          "[stability][thesis]") {
    // Rays from inside aimed at the rim: measured 14,985 of 20,000 (75%) miss entirely.
    const Metrics edges = thesis<collision::Cylinder>(Family::Edges);
    INFO(edges.leaks << " leaks of " << edges.rays);
    CHECK(rate(edges.leaks, edges.rays) > 0.3);
}

TEST_CASE("thesis oriented capsule: the angle-to-Y rotation misplaces hits of rays along the axis",
          "[stability][thesis]") {
    // Parallel family (rays along the capsule's axis): measured t error p99 0.5 (the hit lands
    // on the wrong end); robust p99 2e-5 on the same rays.
    const Metrics parallel = thesis<collision::OrientedCapsule>(Family::Parallel);
    INFO("t p99 " << parallel.t_p99);
    CHECK(parallel.t_p99 > 0.05);
}

TEST_CASE("thesis variants: with no error bound, secondary rays re-hit the surface they leave",
          "[stability][thesis]") {
    // point_error is 0 in every thesis test, so a secondary ray starts at the rounded hit point:
    // measured self-hits of 20,000: sphere 9,464 out / 10,130 in, plane 9,437 / 9,409,
    // triangle 2,487 / 2,480 of ~5,200; the robust routines: none (test_stability_robust.cpp).
    for (Family f : {Family::SurfaceOut, Family::SurfaceIn}) {
        const Metrics sphere = thesis<collision::Sphere>(f);
        const Metrics plane = thesis<collision::Plane>(f);
        const Metrics triangle = thesis<collision::Triangle>(f);
        INFO(family_name(f) << ": sphere " << sphere.self_hits << "/" << sphere.rays << ", plane " << plane.self_hits
                            << "/" << plane.rays << ", triangle " << triangle.self_hits << "/" << triangle.rays);
        CHECK(rate(sphere.self_hits, sphere.rays) > 0.2);
        CHECK(rate(plane.self_hits, plane.rays) > 0.2);
        CHECK(rate(triangle.self_hits, triangle.rays) > 0.2);
    }
}

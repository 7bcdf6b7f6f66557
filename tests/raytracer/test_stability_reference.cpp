// The accuracy reference and the ray families it judges: if these were wrong, every stability
// figure would be too.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

#include "raytracer/accuracy/cases.hpp"
#include "raytracer/accuracy/reference.hpp"

using namespace sweeptrace::accuracy;
using collision::Ray;

TEST_CASE("reference: exact hits, exits from inside, misses", "[stability][reference]") {
    const collision::Sphere s{{0, 0, 0}, 1.0f};
    RefHit h = reference(Ray{{-5, 0, 0}, {1, 0, 0}}, s);
    REQUIRE(h.outcome == RefOutcome::Hit);
    CHECK(h.t == 4.0L);
    h = reference(Ray{{0, 0, 0}, {0, 2, 0}}, s);  // inside: the exit, at t = 1/2
    REQUIRE(h.outcome == RefOutcome::Hit);
    CHECK(h.t == 0.5L);
    CHECK(reference(Ray{{-5, 1.5f, 0}, {1, 0, 0}}, s).outcome == RefOutcome::Miss);
    CHECK(reference(Ray{{5, 0, 0}, {1, 0, 0}}, s).outcome == RefOutcome::Miss);  // behind

    const collision::Aabb box{{0, 0, 0}, {2, 2, 2}};
    h = reference(Ray{{0, 0, -3}, {0, 0, 1}}, box);
    REQUIRE(h.outcome == RefOutcome::Hit);
    CHECK(h.t == 2.0L);
    CHECK(h.normal.z == -1.0L);
    const collision::Capsule cap{{0, 0, 0}, 0.5f, 2.0f};  // extends to y = +-1.5
    h = reference(Ray{{0, 5, 0}, {0, -1, 0}}, cap);
    REQUIRE(h.outcome == RefOutcome::Hit);
    CHECK(h.t == 3.5L);
}

TEST_CASE("reference: touching cases are Boundary, a hair away is decided", "[stability][reference]") {
    const collision::Sphere s{{0, 0, 0}, 1.0f};
    CHECK(reference(Ray{{-5, 1, 0}, {1, 0, 0}}, s).outcome == RefOutcome::Boundary);  // exact tangent
    const float above = std::nextafter(1.0f, 2.0f), below = std::nextafter(1.0f, 0.0f);
    CHECK(reference(Ray{{-5, above, 0}, {1, 0, 0}}, s).outcome == RefOutcome::Miss);
    CHECK(reference(Ray{{-5, below, 0}, {1, 0, 0}}, s).outcome == RefOutcome::Hit);

    const collision::Aabb box{{0, 0, 0}, {2, 2, 2}};
    CHECK(reference(Ray{{-3, 1, 0}, {1, 0, 0}}, box).outcome == RefOutcome::Boundary);  // in the top face
    CHECK(reference(Ray{{-3, below, 0}, {1, 0, 0}}, box).outcome == RefOutcome::Hit);
    CHECK(reference(Ray{{-3, above, 0}, {1, 0, 0}}, box).outcome == RefOutcome::Miss);
    CHECK(reference(Ray{{-3, -1, 0}, {1, 1, 0}}, box).outcome == RefOutcome::Boundary);  // touches an edge
    CHECK(reference(Ray{{-3, -3, 0}, {1, 1, 0}}, box).outcome == RefOutcome::Hit);       // diagonal through

    const collision::Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(reference(Ray{{0.5f, 0, 1}, {0, 0, -1}}, t).outcome == RefOutcome::Boundary);  // on edge ab
    CHECK(reference(Ray{{0.25f, 0.25f, 1}, {0, 0, -1}}, t).outcome == RefOutcome::Hit);
    CHECK(reference(Ray{{0.25f, -0.25f, 1}, {0, 0, -1}}, t).outcome == RefOutcome::Miss);

    const collision::Plane p{{0, 0, 0}, {0, 1, 0}};
    CHECK(reference(Ray{{-1, 0, 0}, {1, 0, 0}}, p).outcome == RefOutcome::Boundary);  // in the plane
    CHECK(reference(Ray{{-1, 1e-30f, 0}, {1, 0, 0}}, p).outcome == RefOutcome::Miss);  // parallel, off it
}

TEST_CASE("reference: across a shared edge exactly one of two triangles is hit, or both are Boundary",
          "[stability][reference]") {
    CaseRng rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int boundary = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 a(u(rng), u(rng), 0.1f * u(rng)), b(u(rng), u(rng), 0.1f * u(rng));
        const glm::vec3 c(u(rng), u(rng), 0.1f * u(rng)), d(u(rng), u(rng), 0.1f * u(rng));
        // abc and bad share edge ab with opposite orientation, as in a closed mesh.
        const collision::Triangle t1{a, b, c}, t2{b, a, d};
        // Aim at a point of the shared edge (rounded), from above.
        const glm::vec3 target = a + u(rng) * 0.5f * (b - a) + 0.5f * (b - a);
        const Ray r{target + glm::vec3(0.1f * u(rng), 0.1f * u(rng), 3.0f), {}};
        Ray ray = r;
        ray.dir = target - r.origin;
        // Seen along the ray both faces must turn the same way (a fold would overlap them).
        const float s1 = glm::dot(glm::cross(b - a, c - a), ray.dir), s2 = glm::dot(glm::cross(a - b, d - b), ray.dir);
        if (!(s1 * s2 > 0.0f)) continue;
        const RefOutcome o1 = reference(ray, t1).outcome, o2 = reference(ray, t2).outcome;
        if (o1 == RefOutcome::Boundary || o2 == RefOutcome::Boundary) {
            CHECK(o1 == o2);  // the shared edge's volume is the same number for both
            ++boundary;
            continue;
        }
        CHECK((o1 == RefOutcome::Hit) != (o2 == RefOutcome::Hit));
    }
    CHECK(boundary < 20000);
}

TEST_CASE("families: the icosphere is closed and oriented outward", "[stability][reference]") {
    const glm::vec3 centre(0.25f, -3.0f, 7.0f);
    const auto tris = icosphere(2, centre, 2.0f);
    REQUIRE(tris.size() == 320);
    std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> directed;
    auto key = [](const glm::vec3& v) { return std::array<float, 3>{v.x, v.y, v.z}; };
    for (const auto& t : tris) {
        CHECK(glm::dot(glm::cross(t.b - t.a, t.c - t.a), (t.a + t.b + t.c) / 3.0f - centre) > 0.0f);
        ++directed[{key(t.a), key(t.b)}];
        ++directed[{key(t.b), key(t.c)}];
        ++directed[{key(t.c), key(t.a)}];
    }
    // Every directed edge once and its reverse once: each edge shared by exactly two faces.
    for (const auto& [edge, count] : directed) {
        CHECK(count == 1);
        CHECK(directed.count({edge.second, edge.first}) == 1);
    }
}

TEST_CASE("families: same seed, same cases, rays from inside the closed meshes start inside",
          "[stability][reference]") {
    const auto a = make_cases<collision::Sphere>(Family::Grazing, 100, 42);
    const auto b = make_cases<collision::Sphere>(Family::Grazing, 100, 42);
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].ray.origin == b[i].ray.origin);
        CHECK(a[i].ray.dir == b[i].ray.dir);
    }
    // Grazing rays really graze: closest approach within a few ulps of the radius.
    for (const auto& c : a) {
        const glm::dvec3 f = glm::dvec3(c.ray.origin - c.shape.center);
        const glm::dvec3 d = glm::normalize(glm::dvec3(c.ray.dir));
        const double miss_distance = glm::length(f - glm::dot(f, d) * d) - double(c.shape.radius);
        CHECK(std::fabs(miss_distance) < 1e-5 * (glm::length(f) + 1.0));
    }
    for (const auto& mesh : make_closed_meshes<collision::Triangle>(512, 3)) {
        for (const auto& r : mesh.rays) {
            // The origin is inside: the line meets the sphere in front of and behind it.
            int front = 0, back = 0;
            for (const auto& f : mesh.faces) {
                const RefSpan s = reference_span(widen(r), f);
                if (!s.meets) continue;
                if (s.t0 > 0) ++front;
                else ++back;
            }
            CHECK(front >= 1);
            CHECK(back >= 1);
        }
    }
}

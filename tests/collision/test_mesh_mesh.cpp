// Mesh-mesh overlap (thesis 3.3): SAT, brute force, 8 octants and BVH agree on a shared set of
// mesh pairs (SAT on convex pairs only, where it tests solids); the thesis's octant vertex rule
// and face-normal-only SAT are shown failing where they do.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "collision/mesh_mesh.hpp"
#include "mesh_fixtures.hpp"
#include "random_cases.hpp"
#include "../shared_meshes.hpp"

using namespace collision;
using testing::TriangleMesh;

namespace {

struct Fixture {
    const char* name;
    TriangleMesh mesh;
    bool convex;
};

std::vector<Fixture> shared_set() {
    std::vector<Fixture> f;
    f.push_back({"box", testing::box_mesh({0.5f, 0.5f, 0.5f}), true});
    f.push_back({"slab", testing::box_mesh({1.0f, 0.1f, 0.6f}), true});
    f.push_back({"sphere", testing::uv_sphere(0.7f, 8, 12), true});
    f.push_back({"torus", testing::torus(0.8f, 0.25f, 16, 8), false});
    f.push_back({"suzanne", testing::read_obj(SWEEPTRACE_SHARED_DIR "/meshes/suzanne.obj"), false});
    return f;
}

// For a closed convex mesh with outward faces: is p inside (or on) it?
bool inside_convex(const TriangleMesh& m, const glm::vec3& p) {
    for (std::size_t i = 0; i < m.triangle_count(); ++i) {
        const Triangle t = m.triangle(i);
        const glm::dvec3 n = glm::cross(glm::dvec3(t.b) - glm::dvec3(t.a), glm::dvec3(t.c) - glm::dvec3(t.a));
        if (glm::dot(n, glm::dvec3(p) - glm::dvec3(t.a)) > 0.0) return false;
    }
    return true;
}

glm::quat random_rotation(testing::SeededRng& rng) {
    const glm::vec3 axis = glm::normalize(rng.vec(-1, 1) + glm::vec3(1e-3f));
    return glm::angleAxis(rng.uniform(0.0f, 6.2831853f), axis);
}

}  // namespace

TEST_CASE("mesh-mesh: SAT, brute force, octants and BVH agree on a shared set", "[mesh]") {
    if (!sweeptrace::test::shared_meshes_available()) return;
    const std::vector<Fixture> set = shared_set();
    testing::SeededRng rng(99);
    int touching = 0, apart = 0, sat_checked = 0, thesis_octant_misses = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const Fixture& fa = set[rng.integer(0, int(set.size()) - 1)];
        const Fixture& fb0 = set[rng.integer(0, int(set.size()) - 1)];
        // Suzanne is the expensive one for brute force: keep it to about a fifth of the trials.
        if ((std::string(fa.name) == "suzanne" || std::string(fb0.name) == "suzanne") && trial % 5 != 0) continue;
        const TriangleMesh a = testing::transformed(fa.mesh, random_rotation(rng), {0, 0, 0});
        const TriangleMesh b = testing::transformed(fb0.mesh, random_rotation(rng), rng.vec(-1.6f, 1.6f));
        INFO("trial " << trial << ": " << fa.name << " vs " << fb0.name);

        const bool brute = overlap_brute(a, b);
        CHECK(overlap_octant(build_octants(a), build_octants(b)) == brute);
        CHECK(overlap_bvh(build_overlap_bvh(a), build_overlap_bvh(b)) == brute);
        CHECK(overlap_bvh(build_overlap_bvh(b), build_overlap_bvh(a)) == brute);
        if (overlap_octant(build_octants(a, OctantRule::vertices), build_octants(b, OctantRule::vertices)) != brute)
            ++thesis_octant_misses;
        if (fa.convex && fb0.convex) {
            // SAT tests solids: it also reports one convex mesh inside the other.
            const bool nested = inside_convex(b, a.vertices[0]) || inside_convex(a, b.vertices[0]);
            const Contact c = overlap_sat(a, b);
            CHECK(c.hit == (brute || nested));
            if (c.hit && glm::length(c.displacement) > 1e-3f) {
                // Moving a by the minimal translation (plus 0.1%) separates the solids.
                const TriangleMesh moved = testing::transformed(a, glm::quat(1, 0, 0, 0), c.displacement * 1.001f);
                CHECK_FALSE(overlap_sat(moved, b).hit);
                CHECK_FALSE(overlap_brute(moved, b));
            }
            ++sat_checked;
        }
        (brute ? touching : apart)++;
    }
    CHECK(touching > 60);
    CHECK(apart > 60);
    CHECK(sat_checked > 80);
    // Not asserted to be nonzero: random placements rarely hit the vertex rule's blind spot;
    // the next test builds one on purpose.
    UNSCOPED_INFO("thesis vertex-rule octant disagreements: " << thesis_octant_misses);
}

TEST_CASE("mesh-mesh: the thesis's octant vertex rule misses a triangle crossing a vertex-less octant",
          "[mesh][octant]") {
    // Mesh a: bounds [-1, 1]^3 (tiny corner triangles), split at 0. Its big triangle at z = 0.5
    // has vertices in octants (-,-,+), (+,-,+), (-,+,+) but covers (0.3, 0.3, 0.5) in (+,+,+).
    TriangleMesh a;
    a.vertices = {{-1, -1, 0.5f}, {1, -0.2f, 0.5f}, {-0.2f, 1, 0.5f},
                  {-1, -1, -1}, {-0.99f, -1, -1}, {-1, -0.99f, -1},
                  {1, 1, 1}, {0.99f, 1, 1}, {1, 0.99f, 1}};
    a.indices = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
    // Mesh b: one small triangle piercing a's big triangle at about (0.31, 0.31, 0.5).
    TriangleMesh b;
    b.vertices = {{0.3f, 0.3f, 0.3f}, {0.35f, 0.3f, 0.7f}, {0.3f, 0.35f, 0.7f}};
    b.indices = {{0, 1, 2}};
    REQUIRE(overlap_brute(a, b));
    CHECK(overlap_octant(build_octants(a), build_octants(b)));
    CHECK(overlap_bvh(build_overlap_bvh(a), build_overlap_bvh(b)));
    CHECK_FALSE(overlap_octant(build_octants(a, OctantRule::vertices), build_octants(b, OctantRule::vertices)));
}

TEST_CASE("mesh-mesh: SAT with face normals only (the thesis's axes) reports an edge-edge near miss",
          "[mesh][sat]") {
    // Two unit cubes, the second turned 45 degrees about x and then about y, placed so that
    // only an edge-edge axis separates them.
    const TriangleMesh a = testing::box_mesh({0.5f, 0.5f, 0.5f});
    const glm::quat q = glm::angleAxis(0.78539816f, glm::vec3(0, 1, 0)) * glm::angleAxis(0.78539816f, glm::vec3(1, 0, 0));
    int found = 0;
    testing::SeededRng rng(12);
    for (int i = 0; i < 2000 && found < 5; ++i) {
        const TriangleMesh b = testing::transformed(testing::box_mesh({0.5f, 0.5f, 0.5f}), q, rng.vec(-1.6f, 1.6f));
        const bool exact = overlap_sat(a, b, SatAxes::faces_and_edges).hit;
        const bool faces = overlap_sat(a, b, SatAxes::faces).hit;
        CHECK((faces || !exact));  // fewer axes can only add false positives
        CHECK(exact == (overlap_brute(a, b) || inside_convex(a, b.vertices[0]) || inside_convex(b, a.vertices[0])));
        if (faces && !exact) ++found;
    }
    CHECK(found > 0);
}

TEST_CASE("mesh-mesh: SAT is for convex meshes only (a concave pair it gets wrong)", "[mesh][sat]") {
    // A small box in the torus's hole: apart, but every projection overlaps.
    const TriangleMesh ring = testing::torus(1.0f, 0.2f, 24, 8);
    const TriangleMesh core = testing::box_mesh({0.2f, 0.2f, 0.2f});
    CHECK_FALSE(overlap_brute(ring, core));
    CHECK(overlap_sat(ring, core).hit);
}

TEST_CASE("mesh-mesh: bad meshes are rejected with a message, empty meshes never touch", "[mesh]") {
    TriangleMesh broken = testing::box_mesh({1, 1, 1});
    broken.indices.push_back({0, 1, 99});
    const TriangleMesh box = testing::box_mesh({1, 1, 1});
    CHECK_THROWS_WITH(overlap_brute(broken, box), Catch::Contains("triangle 12") && Catch::Contains("vertex 99"));
    CHECK_THROWS_AS(overlap_sat(box, broken), std::invalid_argument);
    CHECK_THROWS_AS(build_octants(broken), std::invalid_argument);
    CHECK_THROWS_AS(build_overlap_bvh(broken), std::invalid_argument);
    TriangleMesh nan_mesh = box;
    nan_mesh.vertices[3].y = std::numeric_limits<float>::quiet_NaN();
    CHECK_THROWS_WITH(overlap_brute(box, nan_mesh), Catch::Contains("second mesh") && Catch::Contains("vertex 3"));
    const TriangleMesh empty;
    CHECK_FALSE(overlap_brute(empty, box));
    CHECK_FALSE(overlap_sat(empty, box).hit);
    CHECK_FALSE(overlap_octant(build_octants(empty), build_octants(box)));
    CHECK_FALSE(overlap_bvh(build_overlap_bvh(empty), build_overlap_bvh(box)));
}

// Not a pass/fail test (hidden tag, not registered with ctest): prints how much work and time
// each method needs on a shared mesh pair. Run: build/tests/collision_tests "[.mesh_figures]"
TEST_CASE("mesh-mesh figures", "[.mesh_figures]") {
    if (!sweeptrace::test::shared_meshes_available()) return;
    const TriangleMesh spot = testing::read_obj(SWEEPTRACE_SHARED_DIR "/meshes/spot.obj");
    const TriangleMesh sphere = testing::uv_sphere(0.5f, 32, 64);
    const TriangleMesh cube = testing::box_mesh({0.25f, 0.25f, 0.25f});
    struct Pair {
        const char* name;
        TriangleMesh a, b;
        bool convex;
    };
    const Bounds3 sb = mesh_bounds(spot);
    const glm::vec3 size = sb.hi - sb.lo;
    const std::vector<Pair> pairs = {
        {"cube (12) vs sphere (3968), touching", cube, testing::transformed(sphere, glm::quat(1, 0, 0, 0), {0.7f, 0, 0}), true},
        {"cube (12) vs sphere (3968), apart", cube, testing::transformed(sphere, glm::quat(1, 0, 0, 0), {0.8f, 0, 0}), true},
        {"spot vs spot (5856 each), shifted 40%", spot, testing::transformed(spot, glm::quat(1, 0, 0, 0), size * 0.4f), false},
        {"spot vs spot, shifted to touch bounding boxes only", spot,
         testing::transformed(spot, glm::angleAxis(3.14159265f, glm::vec3(0, 1, 0)), {size.x * 0.95f, 0, 0}), false},
    };
    for (const Pair& p : pairs) {
        std::printf("%s\n", p.name);
        auto run = [&](const char* method, auto&& f) {
            MeshPairStats s;
            const auto t0 = std::chrono::steady_clock::now();
            const bool hit = f(s);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            std::printf("  %-28s hit=%d  %10.3f ms  triangle tests %10llu  box tests %8llu  axes %8llu\n", method, hit, ms,
                        (unsigned long long)s.triangle_tests, (unsigned long long)s.box_tests,
                        (unsigned long long)s.axis_tests);
        };
        run("brute force", [&](MeshPairStats& s) { return overlap_brute(p.a, p.b, &s); });
        run("8 octants (build incl.)", [&](MeshPairStats& s) { return overlap_octant(build_octants(p.a), build_octants(p.b), &s); });
        run("BVH (build incl.)",
            [&](MeshPairStats& s) { return overlap_bvh(build_overlap_bvh(p.a), build_overlap_bvh(p.b), &s); });
        if (p.convex) {
            run("SAT faces (thesis axes)", [&](MeshPairStats& s) { return overlap_sat(p.a, p.b, SatAxes::faces, &s).hit; });
            run("SAT faces+edges", [&](MeshPairStats& s) { return overlap_sat(p.a, p.b, SatAxes::faces_and_edges, &s).hit; });
        }
    }
}

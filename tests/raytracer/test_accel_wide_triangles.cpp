// The AVX2 leaf test (raytracer/accel/wide_kernels_avx2.cpp runs the whole watertight test on 8
// triangles at once) against the scalar path (every triangle through
// collision::intersect_triangle_candidate), on one mesh tree built twice: every hit must be the
// same bit for bit (triangle, t, point, error, normal, uv) and occluded() must agree. The rays
// are chosen where a SIMD test would differ if it rounded differently or took a decision the
// scalar test does not: through vertices and edges (edge functions of exactly 0, which the
// kernel hands to the scalar test), along grid lines of a flat integer mesh, at duplicated
// triangles (ties in t, decided by lane order), at zero-area triangles, with segments ending at
// the surface (the range test) and starting on it (the t > delta_t test), and tmin < 0.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <vector>

#include "accel_test_scenes.hpp"
#include "collision/triangle_watertight.hpp"
#include "raytracer/accel/simd_path.hpp"
#include "raytracer/accel/wide_mesh_bvh.hpp"

using namespace sweeptrace;

namespace {

template <class T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// A flat 12 x 12 grid of unit squares (two triangles each) at z = 0, every third square's
// triangles duplicated, and zero-area triangles (a repeated vertex, three collinear vertices)
// scattered over it; plus a random soup of overlapping triangles above it.
collision::TriangleMesh test_mesh(std::mt19937& rng) {
    collision::TriangleMesh m;
    for (int y = 0; y <= 12; ++y)
        for (int x = 0; x <= 12; ++x) m.vertices.emplace_back(float(x), float(y), 0.0f);
    auto at = [](int x, int y) { return static_cast<unsigned>(y * 13 + x); };
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) {
            const glm::uvec3 a(at(x, y), at(x + 1, y), at(x + 1, y + 1)), b(at(x, y), at(x + 1, y + 1), at(x, y + 1));
            m.indices.push_back(a);
            m.indices.push_back(b);
            if ((x + y) % 3 == 0) m.indices.push_back(a);
            if ((x + 2 * y) % 5 == 0) m.indices.emplace_back(at(x, y), at(x, y), at(x + 1, y + 1));
            if ((x + y) % 7 == 0 && x + 2 <= 12) m.indices.emplace_back(at(x, y), at(x + 1, y), at(x + 2, y));
        }
    std::uniform_real_distribution<float> u(0.0f, 12.0f), h(0.5f, 3.0f), small(-1.0f, 1.0f);
    for (int i = 0; i < 600; ++i) {
        const glm::vec3 c(u(rng), u(rng), h(rng));
        const auto base = static_cast<unsigned>(m.vertices.size());
        for (int k = 0; k < 3; ++k) m.vertices.push_back(c + glm::vec3(small(rng), small(rng), 0.3f * small(rng)));
        m.indices.emplace_back(base, base + 1, base + 2);
    }
    return m;
}

// True when some triangle of the mesh has an edge function of exactly 0 for this ray while
// its other two do not disagree in sign: the lanes the kernel gives to the scalar test.
bool has_zero_edge(const collision::TriangleMesh& mesh, const collision::Ray& ray) {
    const collision::TriangleRay tr = collision::prepare_triangle_ray(ray);
    if (!tr.valid) return false;
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
        const collision::Triangle t = mesh.triangle(i);
        const auto a = collision::shear_vertex(ray, tr, t.a), b = collision::shear_vertex(ray, tr, t.b),
                   c = collision::shear_vertex(ray, tr, t.c);
        if (collision::edge_function(b, c) == 0.0f || collision::edge_function(c, a) == 0.0f ||
            collision::edge_function(a, b) == 0.0f)
            return true;
    }
    return false;
}

struct Counts {
    int hits = 0, zero_edges = 0;
};

void require_same(const WideMeshBvh& scalar, const WideMeshBvh& simd, const collision::Ray& ray, Counts& counts) {
    collision::RayHit a, b;
    std::uint32_t ta = 0, tb = 0;
    const bool ha = scalar.intersect(ray, a, ta), hb = simd.intersect(ray, b, tb);
    REQUIRE(ha == hb);
    REQUIRE(scalar.occluded(ray) == simd.occluded(ray));
    REQUIRE(scalar.occluded(ray) == ha);
    if (!ha) return;
    ++counts.hits;
    REQUIRE(ta == tb);
    REQUIRE(same_bits(a.t, b.t));
    REQUIRE(same_bits(a.point, b.point));
    REQUIRE(same_bits(a.point_error, b.point_error));
    REQUIRE(same_bits(a.normal, b.normal));
    REQUIRE(same_bits(a.uv, b.uv));
}

}  // namespace

TEST_CASE("wide bvh: the AVX2 leaf test hits what the scalar watertight test hits, bit for bit", "[accel][wide]") {
    if (!cpu_has_avx2()) {
        WARN("this CPU has no AVX2: only the scalar kernels run here");
        return;
    }
    std::mt19937 rng(2026);
    const collision::TriangleMesh mesh = test_mesh(rng);
    const WideMeshBvh scalar(mesh, SimdPath::Scalar), simd(mesh, SimdPath::Avx2);
    std::uniform_real_distribution<float> u(-1.0f, 13.0f), up(4.0f, 9.0f), unit(0.0f, 1.0f);
    std::uniform_int_distribution<int> grid(0, 12);
    Counts counts;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 origin(u(rng), u(rng), i % 2 ? up(rng) : -up(rng));
        glm::vec3 target;
        switch (i % 5) {
            case 0: target = glm::vec3(float(grid(rng)), float(grid(rng)), 0.0f); break;               // a grid vertex
            case 1: target = glm::vec3(float(grid(rng)) + 0.5f, float(grid(rng)), 0.0f); break;        // a grid edge
            case 2: target = glm::vec3(float(grid(rng)) + unit(rng), float(grid(rng)) + unit(rng), 0.0f); break;
            case 3: target = mesh.vertices[static_cast<std::size_t>(i) % mesh.vertices.size()]; break;  // any vertex
            default: target = origin + test::random_direction(rng); break;
        }
        collision::Ray ray{origin, target - origin};
        if (i % 7 == 1) ray.tmax = 1.0f;                     // ends at the target, on the surface
        if (i % 7 == 2) ray.tmax = unit(rng);                // ends short of it
        if (i % 11 == 3) ray.tmin = -unit(rng);              // starts behind the origin
        if (i % 13 == 4) ray = collision::Ray{target, glm::vec3(unit(rng) - 0.5f, unit(rng) - 0.5f, 1.0f)};  // leaves the grid
        if (i % 4 == 0 && has_zero_edge(mesh, ray)) ++counts.zero_edges;
        require_same(scalar, simd, ray, counts);
    }
    // An axis-aligned ray down a grid line: edge functions of 0 on every square it passes.
    for (int x = 0; x <= 12; ++x)
        for (int k = 0; k < 8; ++k) {
            const collision::Ray ray{{float(x), -1.0f, 0.0f}, glm::vec3(0.0f, 1.0f, 0.0f)};
            collision::Ray tilted{{float(x), float(k), 5.0f}, glm::vec3(0.0f, 0.25f * float(k - 4), -1.0f)};
            require_same(scalar, simd, ray, counts);
            require_same(scalar, simd, tilted, counts);
        }
    CHECK(counts.hits > 8000);
    CHECK(counts.zero_edges > 300);  // the scalar hand-over is exercised, not just present
}

TEST_CASE("wide bvh: zero-area triangles are left out of the tree, every other triangle kept", "[accel][wide]") {
    std::mt19937 rng(3);
    const collision::TriangleMesh mesh = test_mesh(rng);
    const WideMeshBvh tree(mesh, SimdPath::Scalar);
    std::size_t degenerate = 0;
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
        const collision::Triangle t = mesh.triangle(i);
        const glm::vec3 n = glm::cross(t.b - t.a, t.c - t.a);
        degenerate += !(glm::dot(n, n) > 0.0f);
    }
    REQUIRE(degenerate > 10);
    // Every triangle of non-zero area is found by a short segment through its centroid.
    std::size_t probed = 0;
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
        const collision::Triangle t = mesh.triangle(i);
        const glm::vec3 n = glm::cross(t.b - t.a, t.c - t.a);
        if (!(glm::dot(n, n) > 0.0f)) continue;
        const glm::vec3 centre = (t.a + t.b + t.c) / 3.0f;
        collision::Ray ray{centre + glm::vec3(0.0f, 0.0f, 20.0f), glm::vec3(0.0f, 0.0f, -1.0f)};
        ray.tmax = 20.0f + 1e-3f;
        ray.tmin = 20.0f - 1e-3f;
        if (std::fabs(glm::normalize(n).z) < 0.05f) continue;  // nearly vertical: not aimed at from above
        REQUIRE(tree.occluded(ray));
        ++probed;
    }
    CHECK(probed > 600);
}

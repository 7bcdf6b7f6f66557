// The 8-wide BVH (raytracer/accel/wide_bvh.hpp): the collapse keeps every primitive exactly
// once under boxes that contain it, and the AVX2 kernels give bit for bit the hits of the
// scalar kernels (forced with SimdPath::Scalar) on the same rays: intersect and occluded, on
// analytic shapes, transformed mesh instances, rays from inside closed meshes, and rays aimed
// at shared vertices and edges (where a SIMD pre-filter that rejected too much would leak).
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <vector>

#include "accel_test_scenes.hpp"
#include "collision/bvh.hpp"
#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/accel/sah_cost.hpp"
#include "raytracer/accel/simd_path.hpp"
#include "raytracer/accel/wide_bvh.hpp"
#include "raytracer/accel/wide_mesh_bvh.hpp"

using namespace sweeptrace;

namespace {

bool same_bits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Walks the wide tree: each leaf's slots are marked, and every slot's box must lie inside the
// box its parent holds for the child.
void check_subtree(const WideBvh& tree, std::uint32_t ref, const collision::Bounds3& box,
                   const std::vector<collision::Bounds3>& slot_boxes, std::uint32_t max_leaf, std::vector<int>& seen) {
    if (wide_ref::is_leaf(ref)) {
        REQUIRE(wide_ref::count(ref) <= max_leaf);
        for (std::uint32_t s = wide_ref::first(ref); s < wide_ref::first(ref) + wide_ref::count(ref); ++s) {
            ++seen[s];
            REQUIRE(glm::all(glm::greaterThanEqual(slot_boxes[s].lo, box.lo)));
            REQUIRE(glm::all(glm::lessThanEqual(slot_boxes[s].hi, box.hi)));
        }
        return;
    }
    const WideNode& node = tree.nodes[ref];
    int used = 0;
    for (int i = 0; i < kWideWidth; ++i) {
        if (node.child[i] == wide_ref::empty) continue;
        ++used;
        const collision::Bounds3 child{{node.box[0][0][i], node.box[1][0][i], node.box[2][0][i]},
                                       {node.box[0][1][i], node.box[1][1][i], node.box[2][1][i]}};
        REQUIRE(glm::all(glm::greaterThanEqual(child.lo, box.lo)));
        REQUIRE(glm::all(glm::lessThanEqual(child.hi, box.hi)));
        check_subtree(tree, node.child[i], child, slot_boxes, max_leaf, seen);
    }
    REQUIRE(used >= 2);
}

std::vector<collision::Ray> probe_rays(const Scene& scene, int n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-12.0f, 12.0f);
    std::vector<collision::Ray> rays;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 origin(u(rng), u(rng), u(rng));
        if (i % 3 == 0) {  // at a mesh vertex of some object: shared vertices and edges
            const Object& o = scene.objects[static_cast<std::size_t>(i / 3) % scene.objects.size()];
            if (const auto* m = std::get_if<MeshInstance>(&o.shape)) {
                const auto& v = scene.meshes[m->mesh].triangles.vertices;
                const glm::vec3 target = glm::vec3(o.transform.to_world * glm::vec4(v[(i * 7919u) % v.size()], 1.0f));
                rays.push_back(collision::Ray{origin, target - origin});
                continue;
            }
        }
        rays.push_back(collision::Ray{origin, test::random_direction(rng)});
    }
    return rays;
}

void require_identical(const Accel& scalar, const Accel& simd, const std::vector<collision::Ray>& rays, int& hits) {
    for (const collision::Ray& ray : rays) {
        SurfaceHit a, b;
        const bool ha = scalar.intersect(ray, a), hb = simd.intersect(ray, b);
        REQUIRE(ha == hb);
        REQUIRE(scalar.occluded(ray) == simd.occluded(ray));
        if (!ha) continue;
        ++hits;
        REQUIRE(a.object == b.object);
        REQUIRE(a.primitive == b.primitive);
        REQUIRE(std::memcmp(&a.t, &b.t, sizeof a.t) == 0);
        REQUIRE(same_bits(a.point, b.point));
        REQUIRE(same_bits(a.point_error, b.point_error));
        REQUIRE(same_bits(a.normal, b.normal));
        REQUIRE(same_bits(a.shading_normal, b.shading_normal));
    }
}

}  // namespace

TEST_CASE("wide bvh: the collapse keeps every primitive once, inside every box above it", "[accel][wide]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f), size(0.0f, 0.5f);
    for (int n : {1, 2, 5, 9, 100, 3000}) {
        std::vector<collision::Bounds3> boxes(static_cast<std::size_t>(n));
        std::vector<glm::vec3> centroids;
        for (auto& b : boxes) {
            const glm::vec3 c(u(rng), u(rng), u(rng));
            b = collision::Bounds3{c - size(rng), c + size(rng)};
            centroids.push_back(0.5f * (b.lo + b.hi));
        }
        collision::BvhBuildOptions options;
        options.max_leaf_size = 4;
        const collision::Bvh binary = collision::build_bvh(boxes, centroids, options);
        for (std::uint32_t max_leaf : {4u, 8u}) {
            const WideBvh tree = collapse_to_wide(binary, max_leaf);
            std::vector<collision::Bounds3> slot_boxes;
            for (std::uint32_t p : binary.prim_indices) slot_boxes.push_back(boxes[p]);
            std::vector<int> seen(boxes.size(), 0);
            const collision::Bounds3 root{binary.nodes[0].lo, binary.nodes[0].hi};
            check_subtree(tree, tree.root, root, slot_boxes, max_leaf, seen);
            for (int s : seen) REQUIRE(s == 1);
            REQUIRE(tree.depth <= binary.depth);
            // Each wide node absorbs at least one binary inner node of its own.
            std::size_t inner = 0;
            for (const collision::BvhNode& b : binary.nodes) inner += !b.is_leaf();
            REQUIRE(tree.nodes.size() <= inner);
            REQUIRE(sah_cost(tree) > 0.0);
        }
    }
}

TEST_CASE("wide bvh: the AVX2 kernels give the scalar kernels' hits bit for bit", "[accel][wide]") {
    if (!cpu_has_avx2()) {
        WARN("this CPU has no AVX2: only the scalar kernels run here");
        return;
    }
    int hits = 0;
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        const Scene scene = seed == 3 ? test::mesh_scene(seed) : test::mixed_scene(seed, seed == 2 ? 3.0f : 10.0f);
        const BvhAccel scalar(scene, SimdPath::Scalar), simd(scene, SimdPath::Avx2);
        REQUIRE(scalar.simd_path() == SimdPath::Scalar);
        REQUIRE(simd.simd_path() == SimdPath::Avx2);
        require_identical(scalar, simd, probe_rays(scene, 3000, seed), hits);
    }
    CHECK(hits > 1000);
}

TEST_CASE("wide bvh: rays from inside a closed icosphere hit it on both paths, through vertices and edges",
          "[accel][wide]") {
    const Mesh mesh = test::icosphere(4);
    const WideMeshBvh scalar(mesh.triangles, SimdPath::Scalar);
    const WideMeshBvh simd(mesh.triangles, cpu_has_avx2() ? SimdPath::Avx2 : SimdPath::Scalar);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-0.3f, 0.3f);
    const auto& v = mesh.triangles.vertices;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 origin(u(rng), u(rng), u(rng));
        // Through a vertex, through an edge's midpoint (as rounded), or anywhere.
        const auto& f = mesh.triangles.indices[static_cast<std::size_t>(i) % mesh.triangles.indices.size()];
        const glm::vec3 target = i % 3 == 0 ? v[f.x] : i % 3 == 1 ? 0.5f * (v[f.x] + v[f.y]) : origin + test::random_direction(rng);
        const collision::Ray ray{origin, target - origin};
        collision::RayHit a, b;
        std::uint32_t ta = 0, tb = 0;
        REQUIRE(scalar.intersect(ray, a, ta));
        REQUIRE(simd.intersect(ray, b, tb));
        REQUIRE(ta == tb);
        REQUIRE(std::memcmp(&a.t, &b.t, sizeof a.t) == 0);
        REQUIRE(scalar.occluded(ray));
        REQUIRE(simd.occluded(ray));
    }
}

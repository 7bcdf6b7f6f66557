// The bottom-level BVH over the shared real meshes keeps every triangle reachable: the tree
// holds each triangle once inside its leaf box, and a ray aimed at any triangle's centroid
// along its normal finds a hit no farther than that centroid (the triangle itself, or one in
// front of it), in both the native BVH and Embree.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include <glm/geometric.hpp>

#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/accel/embree_accel.hpp"
#include "raytracer/accel/mesh_ray_bvh.hpp"
#include "raytracer/scene/obj_loader.hpp"
#include "../shared_meshes.hpp"

using namespace sweeptrace;

namespace {

Scene mesh_only(Mesh mesh) {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.meshes.push_back(std::move(mesh));
    Object o;
    o.shape = MeshInstance{0};
    scene.objects.push_back(o);
    return scene;
}

}  // namespace

TEST_CASE("accel: every triangle of the shared meshes is in the tree and reachable by a ray", "[accel][meshes]") {
    if (!sweeptrace::test::shared_meshes_available()) return;
    const std::filesystem::path dir = sweeptrace::test::shared_meshes_dir();
    for (const char* name : {"spot.obj", "fandisk.obj", "suzanne.obj", "teapot.obj", "stanford-bunny.obj"}) {
        INFO(name);
        const Scene scene = mesh_only(load_obj(dir / name));
        const collision::TriangleMesh& tris = scene.meshes[0].triangles;
        const MeshRayBvh mesh_bvh(tris);
        const collision::Bvh& bvh = mesh_bvh.bvh();

        // Structure: each triangle in exactly one leaf, its vertices inside that leaf's box.
        std::vector<int> seen(tris.triangle_count(), 0);
        for (const collision::BvhNode& node : bvh.nodes) {
            if (!node.is_leaf()) continue;
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                const std::uint32_t prim = bvh.prim_indices[i];
                REQUIRE(prim < seen.size());
                ++seen[prim];
                const collision::Triangle t = tris.triangle(prim);
                for (const glm::vec3& v : {t.a, t.b, t.c})
                    REQUIRE((glm::all(glm::lessThanEqual(node.lo, v)) && glm::all(glm::lessThanEqual(v, node.hi))));
            }
        }
        REQUIRE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));

        // Reachability: aim at each triangle's centroid from just off its front side (every
        // triangle of the small meshes, a strided sample of the bunny).
        const BvhAccel native(scene);
        const auto embree = make_embree_accel(scene);
        const std::size_t stride = tris.triangle_count() > 20000 ? 7 : 1;
        const float extent = glm::length(mesh_bvh.bounds().hi - mesh_bvh.bounds().lo);
        int reached = 0, same = 0;
        for (std::size_t i = 0; i < tris.triangle_count(); i += stride) {
            const collision::Triangle t = tris.triangle(i);
            const glm::vec3 n = glm::cross(t.b - t.a, t.c - t.a);
            if (!(glm::dot(n, n) > 0.0f)) continue;  // zero-area triangles cannot be hit
            const glm::vec3 centroid = (t.a + t.b + t.c) / 3.0f;
            const glm::vec3 origin = centroid + 0.01f * extent * glm::normalize(n);
            const collision::Ray ray{origin, centroid - origin, 0.0f, 1.0f + 1e-3f};
            SurfaceHit a, b;
            REQUIRE(native.intersect(ray, a));
            REQUIRE(embree->intersect(ray, b));
            ++reached;
            same += a.primitive == i;
            // suzanne has a face duplicated with opposite winding: either copy may win the tie.
            INFO("t " << a.t << " vs " << b.t);
            CHECK((a.primitive == b.primitive || a.t == b.t));
        }
        // Most rays end on the triangle they aim at (others meet a fold of the mesh first).
        CHECK(same > reached * 9 / 10);
    }
}

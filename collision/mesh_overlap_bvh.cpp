// Mesh-mesh with one BVH per mesh (collision/bvh.hpp), descended in pairs: a node pair whose
// boxes overlap is split by opening the node with the larger surface (or the one that is not
// a leaf) until two leaves meet, whose triangle pairs are tested with Möller. Complete: a
// contact point lies in the box of every node on the path to each triangle's leaf, so the pair
// of leaves holding the two triangles is reached. Roughly O((m + n) log) pairs for meshes that
// barely touch; degrades toward O(m n) as they interpenetrate everywhere.
#include <utility>

#include "collision/mesh_mesh.hpp"
#include "collision/overlap.hpp"

namespace collision {

MeshOverlapBvh build_overlap_bvh(const TriangleMesh& m) {
    validate_mesh(m, "mesh");
    return MeshOverlapBvh{&m, build_triangle_bvh(m)};
}

bool overlap_bvh(const MeshOverlapBvh& a, const MeshOverlapBvh& b, MeshPairStats* stats) {
    validate_mesh(*a.mesh, "first mesh");
    validate_mesh(*b.mesh, "second mesh");
    if (a.bvh.nodes.empty() || b.bvh.nodes.empty()) return false;
    MeshPairStats local;
    bool hit = false;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0u, 0u}};
    while (!stack.empty() && !hit) {
        const auto [ia, ib] = stack.back();
        stack.pop_back();
        const BvhNode& na = a.bvh.nodes[ia];
        const BvhNode& nb = b.bvh.nodes[ib];
        ++local.box_tests;
        if (!boxes_overlap(Bounds3{na.lo, na.hi}, Bounds3{nb.lo, nb.hi})) continue;
        if (na.is_leaf() && nb.is_leaf()) {
            for (std::uint32_t i = na.first; i < na.first + na.count && !hit; ++i) {
                const Triangle ta = a.mesh->triangle(a.bvh.prim_indices[i]);
                for (std::uint32_t j = nb.first; j < nb.first + nb.count; ++j) {
                    ++local.triangle_tests;
                    if (overlap(ta, b.mesh->triangle(b.bvh.prim_indices[j]))) {
                        hit = true;
                        break;
                    }
                }
            }
            continue;
        }
        const bool open_b = na.is_leaf() ||
                            (!nb.is_leaf() && Bounds3{nb.lo, nb.hi}.half_area() > Bounds3{na.lo, na.hi}.half_area());
        if (open_b) {
            stack.emplace_back(ia, nb.first);
            stack.emplace_back(ia, nb.first + 1);
        } else {
            stack.emplace_back(na.first, ib);
            stack.emplace_back(na.first + 1, ib);
        }
    }
    if (stats) {
        stats->box_tests += local.box_tests;
        stats->triangle_tests += local.triangle_tests;
    }
    return hit;
}

}  // namespace collision

#include "raytracer/accel/wide_mesh_bvh.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace sweeptrace {
namespace {

// Leaves of up to 8 triangles: the AVX2 kernel tests 8 at once, so a leaf of 8 costs one step,
// and fewer, fuller leaves mean fewer nodes. Measured on the shared meshes (bench --meshes,
// native / Embree intersect): leaves of 4 gave 0.79-0.92 at 66-80 bytes per triangle, leaves of
// 8 0.85-1.0 at 53-60; leaves of 12 (two AVX2 steps) no better.
constexpr int kLeafTriangles = 8;
static_assert(kLeafTriangles <= static_cast<int>(kMaxLeafTriangles), "the AVX2 kernel tests a leaf in one step");
// The binary build then never splits a range it may leave whole: the collapse would merge any
// subtree of <= 8 triangles into one leaf anyway (same tree, a third less build time).
constexpr float kTraversalCost = 1e30f;

// intersect_triangle_candidate's last check, done once here: a triangle whose cross product is
// 0 or not finite is never hit (same floats, same operations as the test), so it is left out
// of the tree and the SIMD kernel need not test it (wide_traversal.hpp).
bool can_be_hit(const collision::Triangle& t) {
    const glm::vec3 n = glm::cross(t.b - t.a, t.c - t.a);
    const float n2 = glm::dot(n, n);
    return n2 > 0.0f && std::isfinite(n2);
}

// The binary tree over the triangles that can be hit; its prim_indices index `kept`.
collision::Bvh build_binary(const collision::TriangleMesh& mesh, const std::vector<std::uint32_t>& kept) {
    const std::size_t n = kept.size();
    std::vector<collision::Bounds3> boxes(n);
    std::vector<glm::vec3> centroids(n);
    for (std::size_t i = 0; i < n; ++i) {
        const collision::Triangle t = mesh.triangle(kept[i]);
        boxes[i].extend(t.a);
        boxes[i].extend(t.b);
        boxes[i].extend(t.c);
        // The box centre, not the vertex mean: exact to one rounding, and it splits long thin
        // triangles where their extent is.
        centroids[i] = 0.5f * (boxes[i].lo + boxes[i].hi);
    }
    collision::BvhBuildOptions options;
    options.max_leaf_size = kLeafTriangles;
    options.traversal_cost = kTraversalCost;
    return collision::build_bvh(boxes, centroids, options);
}

}  // namespace

WideMeshBvh::WideMeshBvh(const collision::TriangleMesh& mesh, SimdPath path) : kernels_(&wide_kernels(path)) {
    std::vector<std::uint32_t> kept;
    kept.reserve(mesh.triangle_count());
    for (std::uint32_t i = 0; i < mesh.triangle_count(); ++i)
        if (can_be_hit(mesh.triangle(i))) kept.push_back(i);
    const collision::Bvh binary = build_binary(mesh, kept);
    if (!binary.nodes.empty()) bounds_ = collision::Bounds3{binary.nodes[0].lo, binary.nodes[0].hi};
    tree_ = collapse_to_wide(binary, static_cast<std::uint32_t>(kLeafTriangles));
    prims_.reserve(binary.prim_indices.size());
    for (std::uint32_t p : binary.prim_indices) prims_.push_back(kept[p]);
    triangles_.assign(9 * prims_.size() + kWideTrianglePadding, 0.0f);
    // Leaves cover the slots in order, each once: write every leaf's block where its slots are.
    std::vector<std::uint32_t> pending{tree_.root};
    while (!pending.empty()) {
        const std::uint32_t ref = pending.back();
        pending.pop_back();
        if (!wide_ref::is_leaf(ref)) {
            for (std::uint32_t child : tree_.nodes[ref].child) pending.push_back(child);
            continue;
        }
        const std::uint32_t first = wide_ref::first(ref), count = wide_ref::count(ref);
        float* block = triangles_.data() + 9 * static_cast<std::size_t>(first);
        for (std::uint32_t lane = 0; lane < count; ++lane) {
            const collision::Triangle t = mesh.triangle(prims_[first + lane]);
            const glm::vec3* v[3] = {&t.a, &t.b, &t.c};
            for (int vertex = 0; vertex < 3; ++vertex)
                for (int axis = 0; axis < 3; ++axis) block[(3 * vertex + axis) * count + lane] = (*v[vertex])[axis];
        }
    }
}

std::size_t WideMeshBvh::memory_bytes() const {
    return tree_.memory_bytes() + triangles_.capacity() * sizeof(float) + prims_.capacity() * sizeof(std::uint32_t);
}

}  // namespace sweeptrace

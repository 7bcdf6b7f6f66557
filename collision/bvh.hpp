#pragma once
// A bounding volume hierarchy over any primitives given by their axis-aligned boxes (binned SAH,
// Wald 2007). It knows nothing of what the primitives are: the renderer builds one over a mesh's
// triangles and one over a scene's objects, the mesh-mesh overlap test one per mesh.
//
// Layout: a flat array of 32-byte nodes, root at index 0. An inner node's two children are
// adjacent (left at `first`, right at `first + 1`), so a traversal fetches both boxes from one
// cache line pair and needs no second index. A leaf covers prim_indices[first, first + count).
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "collision/bounds3.hpp"

namespace collision {

struct BvhNode {
    glm::vec3 lo;
    std::uint32_t first;  // leaf: first index into Bvh::prim_indices; inner: left child's index
    glm::vec3 hi;
    std::uint32_t count;  // leaf: number of primitives (>= 1); inner: 0
    bool is_leaf() const { return count != 0; }
};
static_assert(sizeof(BvhNode) == 32, "a node must stay 32 bytes (two per 64-byte cache line)");

struct Bvh {
    // A traversal stack of this many entries never overflows: the builder switches from SAH to
    // median splits (which halve the range) below depth 48, and halving 2^32 primitives takes
    // at most 32 more levels.
    static constexpr int max_depth = 80;

    std::vector<BvhNode> nodes;               // empty when built over no primitives
    std::vector<std::uint32_t> prim_indices;  // leaf ranges index this; values index the input
    int depth = 0;                            // levels below the root, <= max_depth

    std::size_t memory_bytes() const {
        return nodes.capacity() * sizeof(BvhNode) + prim_indices.capacity() * sizeof(std::uint32_t);
    }
};

struct BvhBuildOptions {
    int bins = 16;            // SAH candidate planes per axis: bins - 1
    int max_leaf_size = 8;    // a larger range is always split
    float traversal_cost = 1.0f;     // cost of one node visit, relative to
    float intersection_cost = 1.0f;  // the cost of one primitive test
};

// Builds over boxes[i] with representative points centroids[i] (usually the box centres; the
// split decisions use them). Both spans have the same length; every value must be finite.
// Deterministic: the same input gives the same tree. Throws std::invalid_argument on
// mismatched lengths, non-finite input or more than 2^32 - 1 primitives.
Bvh build_bvh(std::span<const Bounds3> boxes, std::span<const glm::vec3> centroids,
              const BvhBuildOptions& options = {});

}  // namespace collision

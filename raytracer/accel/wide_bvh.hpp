#pragma once
// An 8-wide BVH, made by collapsing a binary binned-SAH tree (collision::Bvh) the way Embree
// and tinybvh do: a wide node takes the binary node's two children and keeps opening the child
// with the largest surface area until it has 8 children or only leaves. A binary subtree of at
// most `max_leaf` primitives becomes one leaf, since the SIMD leaf test does a whole leaf at
// once. Leaves reference a contiguous range of the binary tree's prim_indices slots (the binned
// builder partitions in place, so a subtree's primitives are contiguous).
//
// Layout: a node is the 8 children's boxes in SoA form (per axis, 8 lows then 8 highs: one
// 32-byte AVX load each) and 8 child references, 224 bytes. An empty child slot has the box
// lo = +inf, hi = -inf, which no ray with a finite origin enters (and its reference is an
// empty leaf, harmless if a NaN ever lets it through).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision/bvh.hpp"

namespace sweeptrace {

inline constexpr int kWideWidth = 8;

// A child reference: an inner node's index, or a leaf (bit 31) with its first slot (bits 4..30)
// and primitive count (bits 0..3); count 0 is an empty leaf.
namespace wide_ref {
inline constexpr std::uint32_t leaf_bit = 0x80000000u;
inline constexpr std::uint32_t empty = leaf_bit;
inline constexpr std::uint32_t max_leaf_count = 15;
inline constexpr std::uint32_t max_first = (1u << 27) - 1;
inline std::uint32_t leaf(std::uint32_t first, std::uint32_t count) { return leaf_bit | first << 4 | count; }
inline bool is_leaf(std::uint32_t ref) { return (ref & leaf_bit) != 0; }
inline std::uint32_t first(std::uint32_t ref) { return (ref & ~leaf_bit) >> 4; }
inline std::uint32_t count(std::uint32_t ref) { return ref & 15u; }
}  // namespace wide_ref

struct alignas(32) WideNode {
    float box[3][2][kWideWidth];  // [axis][0 = lo, 1 = hi][child]
    std::uint32_t child[kWideWidth];
};
static_assert(sizeof(WideNode) == 224, "a wide node is 7 AVX vectors: 6 box planes and the child references");

struct WideBvh {
    std::vector<WideNode> nodes;             // nodes[0] is the root when `root` is not a leaf
    std::uint32_t root = wide_ref::empty;    // a leaf when the whole tree is one leaf
    // Per node, the axis its children are sorted along (by box centre, lowest first): the
    // any-hit traversal takes the last child along the ray first without comparing distances.
    std::vector<std::uint8_t> axis;
    int depth = 0;                           // levels of wide nodes, <= collision::Bvh::max_depth

    // Entries a traversal stack needs: each level pushes at most kWideWidth - 1 and one is popped.
    static constexpr int stack_size = kWideWidth * (collision::Bvh::max_depth + 1);

    std::size_t memory_bytes() const { return nodes.capacity() * sizeof(WideNode) + axis.capacity(); }
};

// Throws std::length_error when a slot index would not fit a reference (2^27 primitives);
// max_leaf must be in 1..15 and no smaller than the binary tree's largest leaf.
WideBvh collapse_to_wide(const collision::Bvh& bvh, std::uint32_t max_leaf);

// The SAH cost (sah_cost.hpp) of the wide tree, leaves of count primitives.
double sah_cost(const WideBvh& tree);

}  // namespace sweeptrace

#pragma once
// The inner loop shared by both BVH levels: a ray prepared once (inverse direction, which
// child-box face is near), and a slab test against one node's box, inline.
//
// Conservative like collision::intersect_slab (pbrt-v4's Bounds3::IntersectP): each slab
// distance (bound - o) * inv_dir carries at most 3 roundings (subtraction, product, and the
// rounding of inv_dir), a relative error of gamma(3), so enlarging the far distance by
// 1 + 2 gamma(3) never rejects a box the exact ray meets. A zero direction component gives an
// infinite inv_dir; a ray lying exactly in a slab plane then gives 0 * inf = NaN, and the
// comparisons are written so a NaN never shrinks the interval (the box is kept: conservative).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <glm/vec3.hpp>

#include "collision/bvh.hpp"
#include "collision/float_error.hpp"
#include "collision/ray.hpp"

namespace sweeptrace {

struct TraversalRay {
    glm::vec3 origin;
    glm::vec3 inv_dir;
    // Byte offsets, from the start of a BvhNode, of the near and far face coordinate per axis:
    // lo (offset 0) is met first where the dir component is +0 or above, hi (offset 16) where it
    // is -0 or below.
    // Picking faces by offset keeps the box test free of branches and selects.
    std::uint32_t near_offset[3];
    std::uint32_t far_offset[3];

    explicit TraversalRay(const collision::Ray& ray)
        : origin(ray.origin), inv_dir(1.0f / ray.dir.x, 1.0f / ray.dir.y, 1.0f / ray.dir.z) {
        for (int a = 0; a < 3; ++a) {
            const std::uint32_t lo = static_cast<std::uint32_t>(offsetof(collision::BvhNode, lo)) + 4u * a;
            const std::uint32_t hi = static_cast<std::uint32_t>(offsetof(collision::BvhNode, hi)) + 4u * a;
            // By the sign bit, as inv_dir has it: a -0 component has inv_dir -inf, so its near
            // face is hi (a `dir < 0` test took lo, and every box was missed).
            near_offset[a] = std::signbit(ray.dir[a]) ? hi : lo;
            far_offset[a] = std::signbit(ray.dir[a]) ? lo : hi;
        }
    }
};
static_assert(offsetof(collision::BvhNode, lo) == 0 && offsetof(collision::BvhNode, hi) == 16,
              "TraversalRay's face offsets assume lo at byte 0 and hi at byte 16");

inline float node_coordinate(const collision::BvhNode& node, std::uint32_t offset) {
    float v;
    std::memcpy(&v, reinterpret_cast<const unsigned char*>(&node) + offset, sizeof v);
    return v;
}

inline constexpr float kSlabFarScale = 1.0f + 2.0f * collision::gamma(3);

// The slab interval from the three near (t*0) and far (t*1) plane distances, clipped to
// (tmin, tmax): entry distance in t_enter, true when not empty. `new > old ? new : old` keeps
// `old` when `new` is NaN (the wide BVH's AVX2 max/min do the same).
inline bool slab_interval(float tx0, float tx1, float ty0, float ty1, float tz0, float tz1, float tmin, float tmax,
                          float& t_enter) {
    float t0 = tx0 > tmin ? tx0 : tmin;
    t0 = ty0 > t0 ? ty0 : t0;
    t0 = tz0 > t0 ? tz0 : t0;
    float t1 = tx1 < tmax ? tx1 : tmax;
    t1 = ty1 < t1 ? ty1 : t1;
    t1 = tz1 < t1 ? tz1 : t1;
    t_enter = t0;
    return t0 <= t1;
}

// Entry distance of the ray into the node's box within (tmin, tmax), or false.
inline bool enter_box(const collision::BvhNode& node, const TraversalRay& r, float tmin, float tmax, float& t_enter) {
    const float tx0 = (node_coordinate(node, r.near_offset[0]) - r.origin.x) * r.inv_dir.x;
    const float tx1 = (node_coordinate(node, r.far_offset[0]) - r.origin.x) * r.inv_dir.x * kSlabFarScale;
    const float ty0 = (node_coordinate(node, r.near_offset[1]) - r.origin.y) * r.inv_dir.y;
    const float ty1 = (node_coordinate(node, r.far_offset[1]) - r.origin.y) * r.inv_dir.y * kSlabFarScale;
    const float tz0 = (node_coordinate(node, r.near_offset[2]) - r.origin.z) * r.inv_dir.z;
    const float tz1 = (node_coordinate(node, r.far_offset[2]) - r.origin.z) * r.inv_dir.z * kSlabFarScale;
    return slab_interval(tx0, tx1, ty0, ty1, tz0, tz1, tmin, tmax, t_enter);
}

// Visits leaves of `bvh` nearest-first (by box entry), pruning boxes entered beyond the
// current tmax, which `leaf` may lower. leaf(first, count, tmax&) returns true to stop the
// whole traversal (any-hit queries).
template <class Leaf>
inline void traverse(const collision::Bvh& bvh, const TraversalRay& r, float tmin, float& tmax, Leaf&& leaf) {
    if (bvh.nodes.empty()) return;
    const collision::BvhNode* nodes = bvh.nodes.data();
    float t_root;
    if (!enter_box(nodes[0], r, tmin, tmax, t_root)) return;
    struct Entry {
        std::uint32_t node;
        float t_enter;
    };
    Entry stack[collision::Bvh::max_depth + 1];
    int top = 0;
    std::uint32_t current = 0;
    for (;;) {
        const collision::BvhNode& node = nodes[current];
        if (node.is_leaf()) {
            if (leaf(node.first, node.count, tmax)) return;
        } else {
            float t_left, t_right;
            const bool hit_left = enter_box(nodes[node.first], r, tmin, tmax, t_left);
            const bool hit_right = enter_box(nodes[node.first + 1], r, tmin, tmax, t_right);
            if (hit_left && hit_right) {
                const bool left_first = t_left <= t_right;
                current = left_first ? node.first : node.first + 1;
                stack[top++] = Entry{left_first ? node.first + 1 : node.first, left_first ? t_right : t_left};
                continue;
            }
            if (hit_left || hit_right) {
                current = hit_left ? node.first : node.first + 1;
                continue;
            }
        }
        // Pop the next box still nearer than the (possibly lowered) tmax.
        for (;;) {
            if (top == 0) return;
            const Entry e = stack[--top];
            if (e.t_enter <= tmax) {
                current = e.node;
                break;
            }
        }
    }
}

}  // namespace sweeptrace

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
#include <glm/vec3.hpp>

#include "collision/bvh.hpp"
#include "collision/float_error.hpp"
#include "collision/ray.hpp"

namespace sweeptrace {

struct TraversalRay {
    glm::vec3 origin;
    glm::vec3 inv_dir;
    bool negative[3];  // dir component < 0: the box's hi face is the near one

    explicit TraversalRay(const collision::Ray& ray)
        : origin(ray.origin), inv_dir(1.0f / ray.dir.x, 1.0f / ray.dir.y, 1.0f / ray.dir.z),
          negative{ray.dir.x < 0.0f, ray.dir.y < 0.0f, ray.dir.z < 0.0f} {}
};

inline constexpr float kSlabFarScale = 1.0f + 2.0f * collision::gamma(3);

// Entry distance of the ray into the node's box within (tmin, tmax), or false.
inline bool enter_box(const collision::BvhNode& node, const TraversalRay& r, float tmin, float tmax, float& t_enter) {
    float t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        const float near_plane = r.negative[a] ? node.hi[a] : node.lo[a];
        const float far_plane = r.negative[a] ? node.lo[a] : node.hi[a];
        const float tn = (near_plane - r.origin[a]) * r.inv_dir[a];
        const float tf = (far_plane - r.origin[a]) * r.inv_dir[a] * kSlabFarScale;
        t0 = tn > t0 ? tn : t0;
        t1 = tf < t1 ? tf : t1;
    }
    t_enter = t0;
    return t0 <= t1;
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

#pragma once
// The wide BVH's traversals, written once over a kernel K that supplies the two SIMD-able
// steps (K::Boxes: the slab test of a node's 8 child boxes; K::Triangles: the watertight test
// on a leaf's triangles). Only wide_kernels_scalar.cpp and wide_kernels_avx2.cpp include this, each
// with its own kernel, and everything here has internal linkage: the AVX2 unit compiles it for
// AVX2, and no AVX2 copy of a function may be picked by the linker for the scalar path.
//
// Box test: the conservative slab test of bvh_traversal.hpp (far distance enlarged by
// 1 + 2 gamma(3), folded into the far planes' inverse direction, NaN never shrinks the
// interval), lane by lane the same float operations in the same order whatever the kernel, so
// every kernel visits the same nodes in the same order.
// Closest hit visits children nearest entry first (a stack sorted per node) and skips a popped
// box entered beyond the current tmax; occluded() is any-hit: no sorting (the node's last child
// along the ray, in the build's order, first), stops at the first.
//
// Triangle test: the watertight test of collision/triangle_watertight.hpp, unchanged, so its
// stated error bound holds. The AVX2 kernel runs it on the up to 8 triangles of a leaf at once
// with exactly the scalar test's float operations in the scalar test's order (no FMA: the build
// has -ffp-contract=off, "fma" is not in the target, and the kernel uses separate multiply and
// add; max of the magnitudes, the sign flip and IEEE division give the same bits), so every
// lane's values are the scalar test's. Three parts of the scalar test are not in the kernel:
// a lane with an edge function of exactly 0 goes to the scalar test itself (which re-decides it
// in double); the zero-area rejection is done once at build time (wide_mesh_bvh.cpp leaves such
// triangles out, they can never be hit); and the lanes are finished in lane order, each
// re-checked against the tmax lowered by the lanes before it, as the scalar loop sees them.
// Hits are therefore the scalar path's, bit for bit (test_accel_wide_bvh.cpp checks it).
// The mesh leaf loops are flattened (the scalar test inlined into them); in the AVX2 unit that
// compiles the scalar test with VEX encodings but still without FMA.
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

#include "collision/sphere_candidate.hpp"
#include "collision/triangle_watertight.hpp"
#include "raytracer/accel/bvh_traversal.hpp"
#include "raytracer/accel/object_candidates.hpp"
#include "raytracer/accel/wide_bvh.hpp"
#include "raytracer/accel/wide_kernels.hpp"

namespace sweeptrace {
namespace {  // NOLINT: internal linkage on purpose, see above

// The ray as the box test wants it: per axis the byte offset, in a WideNode, of the child
// boxes' near and far planes (lo is near where the direction component is >= 0).
struct WideRay {
    float origin[3];
    float inv_dir[3];
    // inv_dir enlarged for the far planes: (b - o) * (inv_dir * scale) rounds as often as
    // ((b - o) * inv_dir) * scale, 4 roundings, so the slab test's bound (bvh_traversal.hpp)
    // holds unchanged, and a node costs three multiplies less.
    float inv_dir_far[3];
    std::uint32_t near_offset[3], far_offset[3];

    explicit WideRay(const collision::Ray& ray) {
        for (int a = 0; a < 3; ++a) {
            origin[a] = ray.origin[a];
            inv_dir[a] = 1.0f / ray.dir[a];
            inv_dir_far[a] = inv_dir[a] * kSlabFarScale;
            const std::uint32_t lo = static_cast<std::uint32_t>(sizeof(float)) * kWideWidth * (2 * a);
            const std::uint32_t hi = lo + static_cast<std::uint32_t>(sizeof(float)) * kWideWidth;
            // By the sign bit, as inv_dir has it: a -0 component has inv_dir -inf, so its near
            // face is hi (a `dir < 0` test took lo, and every box was missed).
            near_offset[a] = std::signbit(ray.dir[a]) ? hi : lo;
            far_offset[a] = std::signbit(ray.dir[a]) ? lo : hi;
        }
    }
};

inline const float* node_plane(const WideNode& node, std::uint32_t offset) {
    return reinterpret_cast<const float*>(reinterpret_cast<const unsigned char*>(&node) + offset);
}

struct StackEntry {
    std::uint32_t ref;
    float t_enter;
};

// A node with two or three entered boxes (of >= 2), the common cases, without the insertion
// loop of traverse_nearest: the same order (nearer entry first; equal entries, the later lane
// first, as the loop leaves them). Returns false for more boxes.
inline bool enter_two_or_three(const WideNode& node, unsigned mask, const float* t_enter, StackEntry* stack, int& top,
                               std::uint32_t& ref) {
    const unsigned rest = mask & (mask - 1), rest2 = rest & (rest - 1);
    if (rest2 == 0) {
        const int a = std::countr_zero(mask), b = std::countr_zero(rest);
        const bool a_nearer = t_enter[a] < t_enter[b];
        stack[top++] = StackEntry{node.child[a_nearer ? b : a], t_enter[a_nearer ? b : a]};
        ref = node.child[a_nearer ? a : b];
        return true;
    }
    if ((rest2 & (rest2 - 1)) != 0) return false;
    int l0 = std::countr_zero(mask), l1 = std::countr_zero(rest), l2 = std::countr_zero(rest2);
    auto before = [&](int x, int y) { return t_enter[x] < t_enter[y] || (t_enter[x] == t_enter[y] && x > y); };
    if (before(l1, l0)) std::swap(l0, l1);  // a three-comparator sorting network
    if (before(l2, l1)) std::swap(l1, l2);
    if (before(l1, l0)) std::swap(l0, l1);
    stack[top++] = StackEntry{node.child[l2], t_enter[l2]};
    stack[top++] = StackEntry{node.child[l1], t_enter[l1]};
    ref = node.child[l0];
    return true;
}

// Nearest-first traversal; leaf(ref, tmax&) may lower tmax.
template <class K, class Leaf>
inline void traverse_nearest(const WideBvh& tree, const collision::Ray& world, float tmin, float& tmax, Leaf&& leaf) {
    if (wide_ref::is_leaf(tree.root)) {  // one leaf (a scene of one object): no box to test
        leaf(tree.root, tmax);
        return;
    }
    const typename K::Boxes boxes{WideRay(world)};
    StackEntry stack[WideBvh::stack_size];
    int top = 0;
    std::uint32_t ref = tree.root;
    for (;;) {
        if (!wide_ref::is_leaf(ref)) {
            const WideNode& node = tree.nodes[ref];
            alignas(32) float t_enter[kWideWidth];
            unsigned mask = boxes.test(node, tmin, tmax, t_enter);
            if (mask != 0 && (mask & (mask - 1)) == 0) {  // one box: no stack traffic
                ref = node.child[std::countr_zero(mask)];
                continue;
            }
            if (mask != 0 && enter_two_or_three(node, mask, t_enter, stack, top, ref)) continue;
            if (mask != 0) {
                const int base = top;
                do {  // insert sorted: the nearest box ends on top of the stack
                    const int lane = std::countr_zero(mask);
                    mask &= mask - 1;
                    const StackEntry e{node.child[lane], t_enter[lane]};
                    int j = top++;
                    for (; j > base && stack[j - 1].t_enter < e.t_enter; --j) stack[j] = stack[j - 1];
                    stack[j] = e;
                } while (mask != 0);
                ref = stack[--top].ref;
                continue;
            }
        } else {
            leaf(ref, tmax);
        }
        for (;;) {  // pop the next box still entered before the (possibly lowered) tmax
            if (top == 0) return;
            const StackEntry e = stack[--top];
            if (e.t_enter <= tmax) {
                ref = e.ref;
                break;
            }
        }
    }
}

struct NoAnyHook {
    unsigned operator()(std::uint32_t, unsigned, bool&) const { return 0; }
};

// Any-hit traversal: leaf(ref) returns true to stop. any_hook(node index, hit children mask,
// stop&) may finish some hit children at the node (returning their mask; stop = one is hit).
// kBuildOrder: the farthest child by the build's order (meshes); otherwise by entry distance
// (the top level, whose children's sizes vary too much for the order of their centres: on
// scenes/spheres-field.json, native / embree occluded 1.67-1.68 by distance, 1.62-1.63 by order).
enum class FarChild { ByBuildOrder, ByDistance };
template <class K, FarChild kFar = FarChild::ByBuildOrder, class Leaf, class AnyHook = NoAnyHook>
inline bool traverse_any(const WideBvh& tree, const collision::Ray& world, float tmin, float tmax, Leaf&& leaf,
                         AnyHook&& any_hook = {}) {
    if (wide_ref::is_leaf(tree.root)) return leaf(tree.root);
    const typename K::Boxes boxes{WideRay(world)};
    const bool forward[3] = {world.dir.x >= 0.0f, world.dir.y >= 0.0f, world.dir.z >= 0.0f};
    std::uint32_t stack[WideBvh::stack_size];
    int top = 0;
    std::uint32_t ref = tree.root;
    for (;;) {
        if (!wide_ref::is_leaf(ref)) {
            alignas(32) float t_enter[kWideWidth];
            const WideNode& node = tree.nodes[ref];
            unsigned mask = boxes.test(node, tmin, tmax, t_enter);
            bool stop = false;
            mask &= ~any_hook(ref, mask, stop);
            if (stop) return true;
            if (mask != 0) {
                // No sorting, but the farthest box first: a shadow ray starts on a surface, and
                // the boxes it enters first hold that surface, which cannot block it. Measured on
                // bench --meshes shadow rays (medians of 4 runs, native / embree occluded): slot
                // order 0.88-1.08, farthest entry distance first 0.95-1.07 (ogre 0.88 -> 0.95,
                // bunny 0.96 -> 1.00). "Farthest" is now read from the build's order (children
                // sorted along tree.axis) and the ray's direction on that axis, with no compare
                // loop, whose exits the branch predictor kept missing: 3 alternated runs, cow
                // 1.04 -> 1.06-1.08, suzanne 1.03 -> 1.09, teapot 1.05 -> 1.16-1.19, spot 1.11
                // -> 1.12-1.15, bunny 1.02 -> 1.06-1.07; ogre 0.93-1.01 either way in the bench,
                // 0.99-1.00 -> 1.02-1.05 on its shadow rays alone.
                if constexpr (kFar == FarChild::ByDistance) {
                    int far = std::countr_zero(mask);
                    for (unsigned m = mask & (mask - 1); m != 0; m &= m - 1) {
                        const int lane = std::countr_zero(m);
                        if (t_enter[lane] > t_enter[far]) far = lane;
                    }
                    ref = node.child[far];
                    for (mask &= ~(1u << far); mask != 0; mask &= mask - 1) stack[top++] = node.child[std::countr_zero(mask)];
                } else if (forward[tree.axis[ref]]) {  // the last child along the ray first, then back
                    const int far = 31 - std::countl_zero(mask);
                    ref = node.child[far];
                    for (mask &= ~(1u << far); mask != 0; mask &= mask - 1) stack[top++] = node.child[std::countr_zero(mask)];
                } else {
                    const int far = std::countr_zero(mask);
                    ref = node.child[far];
                    for (mask &= mask - 1; mask != 0; mask &= ~(1u << (31 - std::countl_zero(mask))))
                        stack[top++] = node.child[31 - std::countl_zero(mask)];
                }
                continue;
            }
        } else if (leaf(ref)) {
            return true;
        }
        if (top == 0) return false;
        ref = stack[--top];
    }
}

inline glm::vec3 leaf_vertex(const float* block, std::uint32_t count, int vertex, std::uint32_t lane) {
    return {block[(3 * vertex + 0) * count + lane], block[(3 * vertex + 1) * count + lane],
            block[(3 * vertex + 2) * count + lane]};
}

// One leaf of a mesh for the nearest hit: the kernel's lanes that passed against the leaf's
// entry tmax, and the lanes for the scalar test, in lane order as the scalar loop takes them; a
// lane accepted earlier in the leaf lowers tmax, so the kernel's lanes are re-checked against
// it (their only tests that depend on tmax).
template <class K>
inline bool mesh_leaf_nearest(const typename K::Triangles& triangles, const collision::TriangleRay& tr, const float* block,
                              std::uint32_t count, collision::Ray& clipped, collision::TriangleCandidate& best,
                              std::uint32_t& best_lane) {
    LeafCandidates c;
    unsigned exact = 0;
    const unsigned kernel_hits = triangles.test(block, count, clipped.tmin, clipped.tmax, c, exact);
    bool found = false;
    for (unsigned m = kernel_hits | exact; m != 0; m &= m - 1) {
        const auto lane = static_cast<std::uint32_t>(std::countr_zero(m));
        if (!K::Triangles::tests_lanes || ((exact >> lane) & 1u)) {
            if (!collision::intersect_triangle_candidate(clipped, tr, leaf_vertex(block, count, 0, lane),
                                                         leaf_vertex(block, count, 1, lane),
                                                         leaf_vertex(block, count, 2, lane), best))
                continue;
        } else {
            if (!(c.ts[lane] < clipped.tmax * c.abs_det[lane]) || !(c.t[lane] < clipped.tmax)) continue;
            best.t = c.t[lane];
            best.b0 = c.e0[lane] * c.inv_det[lane];
            best.b1 = c.e1[lane] * c.inv_det[lane];
            best.b2 = c.e2[lane] * c.inv_det[lane];
        }
        clipped.tmax = best.t;
        best_lane = lane;
        found = true;
    }
    return found;
}

template <class K>
bool mesh_intersect(const WideMeshView& mesh, const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) {
    const collision::TriangleRay tr = collision::prepare_triangle_ray(ray);
    if (!tr.valid) return false;
    const typename K::Triangles triangles(ray, tr);
    collision::Ray clipped = ray;
    collision::TriangleCandidate best;
    std::uint32_t best_ref = 0, best_lane = 0;
    bool found = false;
    traverse_nearest<K>(*mesh.tree, ray, ray.tmin, clipped.tmax, [&](std::uint32_t ref, float&) __attribute__((flatten)) {
        const std::uint32_t first = wide_ref::first(ref), count = wide_ref::count(ref);
        const float* block = mesh.triangles + 9 * static_cast<std::size_t>(first);
        // Lowers clipped.tmax, the traversal's tmax, with every accepted hit.
        if (mesh_leaf_nearest<K>(triangles, tr, block, count, clipped, best, best_lane)) {
            best_ref = ref;
            found = true;
        }
    });
    if (!found) return false;
    const std::uint32_t first = wide_ref::first(best_ref), count = wide_ref::count(best_ref);
    const float* block = mesh.triangles + 9 * static_cast<std::size_t>(first);
    collision::finish_triangle_hit(leaf_vertex(block, count, 0, best_lane), leaf_vertex(block, count, 1, best_lane),
                                   leaf_vertex(block, count, 2, best_lane), best, hit);
    triangle = mesh.prims[first + best_lane];
    return true;
}

template <class K>
bool mesh_occluded(const WideMeshView& mesh, const collision::Ray& ray) {
    const collision::TriangleRay tr = collision::prepare_triangle_ray(ray);
    if (!tr.valid) return false;
    const typename K::Triangles triangles(ray, tr);
    return traverse_any<K>(*mesh.tree, ray, ray.tmin, ray.tmax, [&](std::uint32_t ref) __attribute__((flatten)) {
        const std::uint32_t first = wide_ref::first(ref), count = wide_ref::count(ref);
        const float* block = mesh.triangles + 9 * static_cast<std::size_t>(first);
        LeafCandidates unused;
        unsigned exact = 0;
        if (triangles.test(block, count, ray.tmin, ray.tmax, unused, exact) != 0) return true;
        collision::TriangleCandidate c;
        for (unsigned m = exact; m != 0; m &= m - 1) {
            const auto lane = static_cast<std::uint32_t>(std::countr_zero(m));
            if (collision::intersect_triangle_candidate(ray, tr, leaf_vertex(block, count, 0, lane),
                                                        leaf_vertex(block, count, 1, lane),
                                                        leaf_vertex(block, count, 2, lane), c))
                return true;
        }
        return false;
    });
}

// A slot's sphere without a transform: what intersect_analytic does, from the slot's copy.
// to_object_space, its identity case (the ray itself, t_shift 0) without the call.
inline ObjectRay object_ray(const Transform& xf, const collision::Ray& ray) {
    return xf.identity ? ObjectRay{ray, 0.0f} : to_object_space(xf, ray);
}

// `t` is the candidate's on this ray.
inline void finish_slot_sphere(const collision::Sphere& sphere, std::uint32_t index, const collision::Ray& ray, float t,
                               SurfaceHit& hit) {
    static const Transform identity;
    collision::RayHit h;
    collision::finish_sphere_hit(ray, sphere, t, h);
    surface_hit_to_world(identity, h, 0.0f, hit);
    hit.object = index;
    hit.primitive = 0;
}

// Mesh instance `index` seen through `xf` (its transform, or its pose at the ray's time).
template <class K>
inline bool instance_intersect(const TopLevelView& top, const MeshInstance& instance, std::uint32_t index,
                               const Transform& xf, const collision::Ray& ray, SurfaceHit& hit) {
    const ObjectRay local = object_ray(xf, ray);
    collision::RayHit h;
    std::uint32_t triangle = 0;
    if (!mesh_intersect<K>(top.meshes[instance.mesh], local.ray, h, triangle)) return false;
    mesh_hit_to_world(top.scene->meshes[instance.mesh], xf, index, triangle, h, local.t_shift, hit);
    return true;
}

template <class K>
bool object_intersect(const TopLevelView& top, std::uint32_t slot, const collision::Ray& ray, SurfaceHit& hit) {
    const std::uint32_t index = top.objects[slot];
    const Object& object = top.scene->objects[index];
    const auto* instance = std::get_if<MeshInstance>(&object.shape);
    if (!instance) return intersect_analytic_object(*top.scene, index, ray, hit);
    return instance_intersect<K>(top, *instance, index, object.transform, ray, hit);
}

template <class K>
bool object_occluded(const TopLevelView& top, std::uint32_t slot, const collision::Ray& ray) {
    float t;
    if (top.spheres[slot].radius > 0.0f) return collision::intersect_sphere_candidate(ray, top.spheres[slot], t);
    const std::uint32_t index = top.objects[slot];
    const Object& object = top.scene->objects[index];
    if (const auto* instance = std::get_if<MeshInstance>(&object.shape))
        return mesh_occluded<K>(top.meshes[instance->mesh], object_ray(object.transform, ray).ray);
    SurfaceHit unused;
    return intersect_analytic_object(*top.scene, index, ray, unused);
}

// The same two at shutter fraction `time`: a moving object in its pose then (one pose per
// candidate test, geometry/motion.hpp), a still one exactly as above. Moving objects never have
// a slot sphere (bvh_accel.cpp leaves them out), so the sphere shortcuts below stay still-only.
template <class K>
bool object_intersect_at(const TopLevelView& top, std::uint32_t slot, const collision::Ray& ray, float time, SurfaceHit& hit) {
    const std::uint32_t index = top.objects[slot];
    const Object& object = top.scene->objects[index];
    if (!object.motion.moving()) return object_intersect<K>(top, slot, ray, hit);
    const auto* instance = std::get_if<MeshInstance>(&object.shape);
    if (!instance) return intersect_object_at(top.scene->objects, top.scene->meshes, index, ray, time, hit);
    return instance_intersect<K>(top, *instance, index, pose_at(object.motion, time), ray, hit);
}

template <class K>
bool object_occluded_at(const TopLevelView& top, std::uint32_t slot, const collision::Ray& ray, float time) {
    float t;
    if (top.swept[slot].sphere.radius > 0.0f) return collision::intersect_sphere_candidate(ray, top.swept[slot].at(time), t);
    const std::uint32_t index = top.objects[slot];
    const Object& object = top.scene->objects[index];
    if (!object.motion.moving()) return object_occluded<K>(top, slot, ray);
    if (const auto* instance = std::get_if<MeshInstance>(&object.shape))
        return mesh_occluded<K>(top.meshes[instance->mesh], to_object_space(pose_at(object.motion, time), ray).ray);
    SurfaceHit unused;
    return intersect_object_at(top.scene->objects, top.scene->meshes, index, ray, time, unused);
}

// The nearest hit over the objects. A slot's sphere is only decided (its t) when tested; the
// nearest one is finished once at the end, on the ray it was decided on, which gives the hit
// the full test would have written then (sphere_candidate.hpp). Any other object's hit is
// written when found, and a later, nearer one overwrites either.
// kTimed: at shutter fraction `time` (object_intersect_at); otherwise `time` is unused and the
// code is the still scenes' own.
template <class K, bool kTimed>
inline bool top_nearest(const TopLevelView& top, const collision::Ray& ray, SurfaceHit& hit, float time) {
    float tmax = ray.tmax;
    bool found = false;
    std::uint32_t sphere_slot = 0;
    float sphere_t = 0.0f;
    bool sphere_pending = false;
    collision::Ray sphere_ray = ray;
    [[maybe_unused]] collision::Sphere swept_at{glm::vec3(0.0f), 0.0f};  // kTimed: the pending swept sphere, if it is one
    traverse_nearest<K>(*top.tree, ray, ray.tmin, tmax, [&](std::uint32_t ref, float& t_limit) __attribute__((always_inline)) {
        const std::uint32_t first = wide_ref::first(ref), end = first + wide_ref::count(ref);
        for (std::uint32_t i = first; i < end; ++i) {
            collision::Ray clipped = ray;
            clipped.tmax = t_limit;
            float t;
            if constexpr (kTimed) {
                if (top.swept[i].sphere.radius > 0.0f) {  // a swept sphere: as a slot sphere, at the ray's time
                    const collision::Sphere s = top.swept[i].at(time);
                    if (!collision::intersect_sphere_candidate(clipped, s, t)) continue;
                    sphere_ray = clipped;
                    sphere_slot = i;
                    sphere_t = t;
                    sphere_pending = true;
                    swept_at = s;
                    t_limit = t < t_limit ? t : t_limit;
                    found = true;
                    continue;
                }
            }
            if (top.spheres[i].radius > 0.0f) {
                if (!collision::intersect_sphere_candidate(clipped, top.spheres[i], t)) continue;
                sphere_ray = clipped;
                sphere_slot = i;
                sphere_t = t;
                sphere_pending = true;
                t += 0.0f;  // the identity's t_shift, as surface_hit_to_world adds it
            } else {
                if constexpr (kTimed) {
                    if (!object_intersect_at<K>(top, i, clipped, time, hit)) continue;
                } else {
                    if (!object_intersect<K>(top, i, clipped, hit)) continue;
                }
                sphere_pending = false;
                t = hit.t;
            }
            // A transformed object's t = s + t_shift rounds once more; keep tmax monotone.
            t_limit = t < t_limit ? t : t_limit;
            found = true;
        }
    });
    if constexpr (kTimed) {
        if (sphere_pending && top.swept[sphere_slot].sphere.radius > 0.0f) {
            finish_slot_sphere(swept_at, top.objects[sphere_slot], sphere_ray, sphere_t, hit);
            return found;
        }
    }
    if (sphere_pending) finish_slot_sphere(top.spheres[sphere_slot], top.objects[sphere_slot], sphere_ray, sphere_t, hit);
    return found;
}

// Any hit over the objects. The sphere children of a node are decided together at the node
// (K::Spheres: all at once, or each by the scalar candidate test), since any-hit has no order to
// keep; measured on scenes/spheres-field.json, native / embree occluded 1.67 -> 1.72 (medians
// of 5 runs, interleaved). The same at the nearest-hit traversal measured slower (1.46 -> 1.37): it tests
// spheres a nearer hit would have culled.
template <class K, bool kTimed>
inline bool top_any(const TopLevelView& top, const collision::Ray& ray, float time) {
    auto leaf = [&](std::uint32_t ref) __attribute__((always_inline)) {
        const std::uint32_t first = wide_ref::first(ref), end = first + wide_ref::count(ref);
        for (std::uint32_t i = first; i < end; ++i) {
            if constexpr (kTimed) {
                if (object_occluded_at<K>(top, i, ray, time)) return true;
            } else {
                if (object_occluded<K>(top, i, ray)) return true;
            }
        }
        return false;
    };
    if (wide_ref::is_leaf(top.tree->root)) return leaf(top.tree->root);  // one object: no node, no sphere set-up
    const typename K::Spheres spheres(ray);
    auto node = [&](std::uint32_t index, unsigned mask, bool& stop) __attribute__((always_inline)) {
        LaneTimes times;
        unsigned scalar = 0, taken = 0;
        stop = spheres.test(top.child_spheres[index], mask, ray.tmin, ray.tmax, times, scalar, taken) != 0;
        float t;
        for (unsigned m = scalar; m != 0 && !stop; m &= m - 1) {
            const std::uint32_t slot = wide_ref::first(top.tree->nodes[index].child[std::countr_zero(m)]);
            stop = collision::intersect_sphere_candidate(ray, top.spheres[slot], t);
        }
        return taken;
    };
    return traverse_any<K, FarChild::ByDistance>(*top.tree, ray, ray.tmin, ray.tmax, leaf, node);
}

template <class K>
bool top_intersect(const TopLevelView& top, const collision::Ray& ray, SurfaceHit& hit) {
    return top_nearest<K, false>(top, ray, hit, 0.0f);
}

template <class K>
bool top_occluded(const TopLevelView& top, const collision::Ray& ray) {
    return top_any<K, false>(top, ray, 0.0f);
}

template <class K>
bool top_intersect_at(const TopLevelView& top, const collision::Ray& ray, float time, SurfaceHit& hit) {
    return top_nearest<K, true>(top, ray, hit, time);
}

template <class K>
bool top_occluded_at(const TopLevelView& top, const collision::Ray& ray, float time) {
    return top_any<K, true>(top, ray, time);
}

template <class K>
constexpr WideKernels make_kernels() {
    return WideKernels{&mesh_intersect<K>,  &mesh_occluded<K>,    &top_intersect<K>,
                       &top_occluded<K>,    &top_intersect_at<K>, &top_occluded_at<K>};
}

}  // namespace
}  // namespace sweeptrace

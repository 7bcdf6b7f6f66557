#pragma once
// The wide BVH's queries, one set of functions per instruction set (simd_path.hpp), reached
// through one table lookup per ray: the scalar set in wide_kernels_scalar.cpp, the AVX2 set in
// wide_kernels_avx2.cpp, both instantiated from wide_traversal.hpp.
#include <cstdint>

#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "collision/shapes.hpp"
#include "raytracer/accel/simd_path.hpp"
#include "raytracer/accel/wide_bvh.hpp"
#include "raytracer/geometry/intersect_object.hpp"
#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// A mesh's wide tree and its triangles, ready for the test: leaf ref (first, count) owns the
// floats triangles[9 first, 9 (first + count)), laid out [vertex a, b, c][axis x, y, z][count]
// so one SIMD load takes one coordinate of every triangle of the leaf (the array is padded so
// a full-width load past the last leaf stays inside it); prims[slot] is the mesh triangle.
struct WideMeshView {
    const WideBvh* tree = nullptr;
    const float* triangles = nullptr;
    const std::uint32_t* prims = nullptr;
};

// The top level: a wide tree over the objects (slot -> object index) and per Scene::meshes
// entry its view (tree null when no object uses it). Spheres without a transform are copied
// per slot (radius 0 in the other slots), so the most common analytic candidate is tested from
// 16 contiguous bytes instead of its Object's few hundred.
// Per top-level node, its children that are one-object leaves holding such a sphere, in SoA
// form (radius 0 for every other child), so the traversal tests them together at the node.
struct alignas(32) ChildSpheres {
    float x[8], y[8], z[8], r[8];
};

struct TopLevelView {
    const Scene* scene = nullptr;
    const WideBvh* tree = nullptr;
    const std::uint32_t* objects = nullptr;
    const collision::Sphere* spheres = nullptr;
    const WideMeshView* meshes = nullptr;
    const ChildSpheres* child_spheres = nullptr;  // per tree node
    // A moving scene's time slices: per slot its swept sphere (radius 0 for every other object),
    // tested by the timed queries like a slot sphere, at the ray's time.
    const SweptSphere* swept = nullptr;
};

// Per lane of a node, a kernel's sphere test's t.
struct alignas(32) LaneTimes {
    float t[8];
};

struct WideKernels {
    // Nearest triangle with ray.tmin < t < ray.tmax, object space: hit and mesh triangle index.
    bool (*mesh_intersect)(const WideMeshView&, const collision::Ray&, collision::RayHit&, std::uint32_t&);
    bool (*mesh_occluded)(const WideMeshView&, const collision::Ray&);
    // The Accel queries over every object.
    bool (*top_intersect)(const TopLevelView&, const collision::Ray&, SurfaceHit&);
    bool (*top_occluded)(const TopLevelView&, const collision::Ray&);
    // The same at a shutter fraction (geometry/motion.hpp): moving objects in their pose then.
    bool (*top_intersect_at)(const TopLevelView&, const collision::Ray&, float, SurfaceHit&);
    bool (*top_occluded_at)(const TopLevelView&, const collision::Ray&, float);
};

extern const WideKernels kScalarKernels;
extern const WideKernels kAvx2Kernels;  // call only when cpu_has_avx2()

inline const WideKernels& wide_kernels(SimdPath path) { return path == SimdPath::Avx2 ? kAvx2Kernels : kScalarKernels; }

// A mesh leaf holds at most this many triangles: the AVX2 kernel tests a whole leaf in one step.
inline constexpr std::uint32_t kMaxLeafTriangles = 8;

// Per lane of a leaf, what a kernel's triangle test leaves for the traversal to finish a hit
// with: t, the range test's ts and |det|, 1 / det and the three edge functions.
struct alignas(32) LeafCandidates {
    float t[8], ts[8], abs_det[8], inv_det[8], e0[8], e1[8], e2[8];
};

// Floats of padding after the last leaf: the widest load (8) may start at the last float.
inline constexpr int kWideTrianglePadding = 8;

}  // namespace sweeptrace

#pragma once
// The bottom level: one mesh's triangles under an 8-wide BVH (wide_bvh.hpp) in the mesh's own
// (object) space, built once and shared by every object that instances it. Built from the
// binary binned-SAH tree, collapsed; leaves hold up to 8 triangles stored in leaf
// order, vertex coordinates in SoA form (wide_kernels.hpp), so a leaf's data is contiguous
// and one SIMD load reads one coordinate of all its triangles. Triangles of zero area, which the
// watertight test never hits, are left out (wide_mesh_bvh.cpp).
#include <cstdint>
#include <vector>

#include "collision/bvh.hpp"
#include "collision/hit.hpp"
#include "collision/mesh.hpp"
#include "collision/ray.hpp"
#include "raytracer/accel/simd_path.hpp"
#include "raytracer/accel/wide_bvh.hpp"
#include "raytracer/accel/wide_kernels.hpp"

namespace sweeptrace {

class WideMeshBvh {
public:
    explicit WideMeshBvh(const collision::TriangleMesh& mesh, SimdPath path = default_simd_path());

    // Nearest triangle hit with ray.tmin < t < ray.tmax (object space): writes hit and the
    // mesh's triangle index only when found. The watertight test of triangle_watertight.hpp.
    bool intersect(const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) const {
        return kernels_->mesh_intersect(view(), ray, hit, triangle);
    }
    bool occluded(const collision::Ray& ray) const { return kernels_->mesh_occluded(view(), ray); }

    // Box of every vertex of a triangle that can be hit (not of zero area), in object space;
    // empty when there is none.
    const collision::Bounds3& bounds() const { return bounds_; }
    std::size_t memory_bytes() const;
    double sah_cost() const { return sweeptrace::sah_cost(tree_); }
    const WideBvh& tree() const { return tree_; }
    WideMeshView view() const { return WideMeshView{&tree_, triangles_.data(), prims_.data()}; }

private:
    WideBvh tree_;
    std::vector<float> triangles_;     // per leaf: [vertex][axis][count] floats, then padding
    std::vector<std::uint32_t> prims_;  // slot -> mesh triangle index
    collision::Bounds3 bounds_;
    const WideKernels* kernels_;
};

}  // namespace sweeptrace

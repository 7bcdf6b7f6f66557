#pragma once
// Boxes of a mesh's triangles, and the BVH over them: what the mesh-mesh overlap test
// (mesh_mesh.hpp) and the renderer's ray structures over a mesh both start from, in one place.
#include <cstddef>

#include "collision/bounds3.hpp"
#include "collision/bvh.hpp"
#include "collision/mesh.hpp"

namespace collision {

// Corner bounds of triangle i and of the whole mesh (empty Bounds3 for an empty mesh).
Bounds3 triangle_bounds(const TriangleMesh& m, std::size_t i);
Bounds3 mesh_bounds(const TriangleMesh& m);

// A BVH over triangle_bounds(m, i), split at the boxes' centres; primitive indices are triangle
// indices. The mesh must be finite with indices in range (build_bvh throws otherwise).
Bvh build_triangle_bvh(const TriangleMesh& m, const BvhBuildOptions& options = {});

}  // namespace collision

#pragma once
// The bottom level: a BVH over one mesh's triangles in the mesh's own (object) space, built
// once and shared by every object that instances the mesh. Triangles are copied in leaf order,
// so a leaf's vertices are contiguous in memory (no index gather in the inner loop).
#include <cstdint>
#include <vector>

#include "collision/bounds3.hpp"
#include "collision/bvh.hpp"
#include "collision/hit.hpp"
#include "collision/mesh.hpp"
#include "collision/ray.hpp"

namespace sweeptrace {

class MeshRayBvh {
public:
    explicit MeshRayBvh(const collision::TriangleMesh& mesh);

    // Nearest triangle hit with ray.tmin < t < ray.tmax (object space): writes hit and the
    // mesh's triangle index only when found.
    bool intersect(const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) const;
    bool occluded(const collision::Ray& ray) const;

    // Box of every vertex used by a triangle, in object space (empty for an empty mesh).
    collision::Bounds3 bounds() const;
    std::size_t memory_bytes() const;
    const collision::Bvh& bvh() const { return bvh_; }

private:
    collision::Bvh bvh_;
    std::vector<collision::Triangle> triangles_;  // triangles_[i] is mesh triangle prim_indices[i]
};

}  // namespace sweeptrace

#pragma once
// The thesis's 8-octant subdivision (§3.3) turned into a ray structure over one mesh: the mesh's
// bounding box split once into 8 octants, each listing the triangles whose bounding box
// overlaps it (collision::build_octants, the partition the mesh-mesh test uses). A ray visits
// the octants it meets, nearest entry first, and stops when its hit lies before the next
// octant. Kept only to be measured against the BVH (a one-level octree cannot adapt to where
// the triangles are).
#include <cstdint>

#include "collision/hit.hpp"
#include "collision/mesh.hpp"
#include "collision/mesh_mesh.hpp"
#include "collision/ray.hpp"

namespace sweeptrace {

class MeshRayOctants {
public:
    explicit MeshRayOctants(const collision::TriangleMesh& mesh);
    bool intersect(const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) const;

private:
    // The mesh-mesh test's partition (collision/mesh_mesh.hpp), by bounding-box overlap.
    collision::OctantPartition octants_;
};

}  // namespace sweeptrace

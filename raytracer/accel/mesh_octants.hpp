#pragma once
// The thesis's 8-octant subdivision (§3.3) turned into a ray structure over one mesh: the mesh's
// bounding box split once into 8 octants, each listing the triangles whose bounding box
// overlaps it. A ray visits the octants it meets, nearest entry first, and stops when its hit
// lies before the next octant. Kept only to be measured against the BVH (a one-level octree
// cannot adapt to where the triangles are).
#include <array>
#include <cstdint>
#include <vector>

#include "collision/bounds3.hpp"
#include "collision/hit.hpp"
#include "collision/mesh.hpp"
#include "collision/ray.hpp"

namespace sweeptrace {

class MeshOctants {
public:
    explicit MeshOctants(const collision::TriangleMesh& mesh);
    bool intersect(const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) const;
    std::size_t memory_bytes() const;

private:
    const collision::TriangleMesh* mesh_;
    collision::Bounds3 bounds_;
    glm::vec3 mid_{0.0f};
    std::array<std::vector<std::uint32_t>, 8> octants_;
};

}  // namespace sweeptrace

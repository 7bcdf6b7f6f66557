#pragma once
// The thesis's hashed uniform grid (§3.4, collision/hashed_grid.hpp) as a ray structure over one
// mesh: triangles inserted by bounding box, rays walked cell by cell with a 3D-DDA (Amanatides &
// Woo 1987) that looks each cell up in the hash table. Kept to be measured against the BVH.
#include <cstdint>

#include "collision/bounds3.hpp"
#include "collision/hashed_grid.hpp"
#include "collision/hit.hpp"
#include "collision/mesh.hpp"
#include "collision/ray.hpp"

namespace sweeptrace {

class MeshHashedGrid {
public:
    // Cell side = the mesh's mean edge length (see the .cpp for why), unless given.
    explicit MeshHashedGrid(const collision::TriangleMesh& mesh, float cell_size = 0.0f);
    bool intersect(const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) const;
    float cell_size() const { return grid_.cell_size(); }
    std::size_t occupied_cells() const { return grid_.occupied_cells(); }

private:
    const collision::TriangleMesh* mesh_;
    collision::Bounds3 bounds_;
    collision::HashedGrid<> grid_;
};

}  // namespace sweeptrace

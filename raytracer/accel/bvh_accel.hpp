#pragma once
// The native two-level BVH: a binned-SAH tree over the objects' world boxes on top, and one
// MeshBvh per mesh below, traversed in the instancing object's space (a transformed mesh is
// never copied or re-built).
#include <memory>
#include <vector>

#include "collision/bvh.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/accel/mesh_bvh.hpp"

namespace sweeptrace {

class BvhAccel final : public Accel {
public:
    explicit BvhAccel(const Scene& scene);

    bool intersect(const collision::Ray& ray, SurfaceHit& hit) const override;
    bool occluded(const collision::Ray& ray) const override;
    std::size_t memory_bytes() const override;
    std::string name() const override { return "bvh"; }

    // Triangles in the meshes the scene's objects instance (each mesh counted once).
    std::size_t triangle_count() const;
    // SAH cost (sah_cost.hpp) of the bottom-level tree of Scene::meshes[mesh]; 0 if unused.
    double mesh_sah_cost(std::size_t mesh) const;

private:
    bool intersect_one(std::uint32_t object, const collision::Ray& ray, SurfaceHit& hit) const;
    bool occluded_one(std::uint32_t object, const collision::Ray& ray) const;

    const Scene& scene_;
    collision::Bvh top_;                             // over the objects; prim indices are object indices
    std::vector<std::unique_ptr<MeshBvh>> meshes_;   // per Scene::meshes entry; null if no object uses it
};

}  // namespace sweeptrace

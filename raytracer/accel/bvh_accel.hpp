#pragma once
// The native two-level BVH: an 8-wide tree (wide_bvh.hpp) over the objects' world boxes on top,
// and one WideMeshBvh per mesh below, traversed in the instancing object's space (a transformed
// mesh is never copied or re-built). Both levels are binned-SAH binary trees collapsed to 8-wide
// nodes; the traversal's instruction set is picked at run time (simd_path.hpp). A moving object's
// top-level box holds it over the whole shutter (geometry/motion.hpp, motion_world_bounds), and
// the queries with a time test it in its pose then.
#include <memory>
#include <vector>

#include "raytracer/accel/accel.hpp"
#include "raytracer/accel/simd_path.hpp"
#include "raytracer/accel/wide_bvh.hpp"
#include "raytracer/accel/wide_kernels.hpp"
#include "raytracer/accel/wide_mesh_bvh.hpp"

namespace sweeptrace {

class BvhAccel final : public Accel {
public:
    explicit BvhAccel(const Scene& scene, SimdPath path = default_simd_path());
    BvhAccel(const BvhAccel&) = delete;  // view_ points into the members
    BvhAccel& operator=(const BvhAccel&) = delete;

    bool intersect(const collision::Ray& ray, SurfaceHit& hit) const override {
        return kernels_->top_intersect(view_, ray, hit);
    }
    bool occluded(const collision::Ray& ray) const override { return kernels_->top_occluded(view_, ray); }
    // A scene with nothing moving takes the still queries, whatever the time.
    bool intersect(const collision::Ray& ray, float time, SurfaceHit& hit) const override {
        return moving_ ? kernels_->top_intersect_at(view_, ray, time, hit) : kernels_->top_intersect(view_, ray, hit);
    }
    bool occluded(const collision::Ray& ray, float time) const override {
        return moving_ ? kernels_->top_occluded_at(view_, ray, time) : kernels_->top_occluded(view_, ray);
    }
    std::size_t memory_bytes() const override;
    std::string name() const override { return "bvh"; }

    // Triangles in the meshes the scene's objects instance (each mesh counted once).
    std::size_t triangle_count() const;
    // SAH cost (sah_cost.hpp) of the bottom-level tree of Scene::meshes[mesh]; 0 if unused.
    double mesh_sah_cost(std::size_t mesh) const;
    SimdPath simd_path() const { return path_; }

private:
    const Scene& scene_;
    SimdPath path_;
    const WideKernels* kernels_;
    WideBvh top_;                                       // over the objects
    std::vector<std::uint32_t> top_objects_;            // top-level slot -> object index
    std::vector<collision::Sphere> top_spheres_;        // slot -> its untransformed sphere, or radius 0
    std::vector<ChildSpheres> top_child_spheres_;       // per top node: its children's spheres
    std::vector<std::unique_ptr<WideMeshBvh>> meshes_;  // per Scene::meshes entry; null if no object uses it
    std::vector<WideMeshView> mesh_views_;              // the same, as the kernels read them
    TopLevelView view_;
    bool moving_ = false;  // some object moves: its box holds it over the whole shutter
};

}  // namespace sweeptrace

#pragma once
// The native two-level BVH: an 8-wide tree (wide_bvh.hpp) over the objects' world boxes on top,
// and one WideMeshBvh per mesh below, traversed in the instancing object's space (a transformed
// mesh is never copied or re-built). Both levels are binned-SAH binary trees collapsed to 8-wide
// nodes; the traversal's instruction set is picked at run time (simd_path.hpp). A moving object's
// top-level box holds it over the whole shutter (geometry/motion.hpp, motion_world_bounds), and
// the queries with a time test it in its pose then, through a top level of their time slice.
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
    // A scene with nothing moving takes the still queries, whatever the time; a moving one the
    // top level of the time slice holding `time`.
    bool intersect(const collision::Ray& ray, float time, SurfaceHit& hit) const override {
        if (slices_.empty()) return kernels_->top_intersect(view_, ray, hit);
        return kernels_->top_intersect_at(slice_at(time).view, ray, time, hit);
    }
    bool occluded(const collision::Ray& ray, float time) const override {
        if (slices_.empty()) return kernels_->top_occluded(view_, ray);
        return kernels_->top_occluded_at(slice_at(time).view, ray, time);
    }
    std::size_t memory_bytes() const override;
    std::string name() const override { return "bvh"; }

    // Triangles in the meshes the scene's objects instance (each mesh counted once).
    std::size_t triangle_count() const;
    // SAH cost (sah_cost.hpp) of the bottom-level tree of Scene::meshes[mesh]; 0 if unused.
    double mesh_sah_cost(std::size_t mesh) const;
    SimdPath simd_path() const { return path_; }
    // Top levels the shutter is split into (0 for a still scene; time_slices.hpp says how many).
    std::size_t time_slices() const { return slices_.size(); }

private:
    // One top level: a wide tree over the objects' boxes and what its kernels read beside it.
    struct TopLevel {
        WideBvh tree;
        std::vector<std::uint32_t> objects;       // slot -> object index
        std::vector<collision::Sphere> spheres;   // slot -> its untransformed still sphere, or radius 0
        std::vector<ChildSpheres> child_spheres;  // per node: its children's spheres
        std::vector<SweptSphere> swept;           // slot -> its swept sphere (geometry/intersect_object.hpp), or radius 0
        TopLevelView view;
        std::size_t memory_bytes() const;
    };
    void build_top(const std::vector<collision::Bounds3>& boxes, const std::vector<std::uint32_t>& object_of,
                   WideBvh& tree, std::vector<std::uint32_t>& objects, std::vector<collision::Sphere>& spheres,
                   std::vector<ChildSpheres>& child_spheres, TopLevelView& view) const;
    const TopLevel& slice_at(float time) const {
        const float x = time * static_cast<float>(slices_.size());
        const std::size_t k = x > 0.0f ? static_cast<std::size_t>(x) : 0;  // NaN and negatives: the first
        return *slices_[k < slices_.size() ? k : slices_.size() - 1];
    }

    const Scene& scene_;
    SimdPath path_;
    const WideKernels* kernels_;
    WideBvh top_;                                       // over the objects (a moving one: over the whole shutter)
    std::vector<std::uint32_t> top_objects_;            // top-level slot -> object index
    std::vector<collision::Sphere> top_spheres_;        // slot -> its untransformed sphere, or radius 0
    std::vector<ChildSpheres> top_child_spheres_;       // per top node: its children's spheres
    std::vector<std::unique_ptr<WideMeshBvh>> meshes_;  // per Scene::meshes entry; null if no object uses it
    std::vector<WideMeshView> mesh_views_;              // the same, as the kernels read them
    TopLevelView view_;
    // With moving objects: the shutter cut into equal slices, each with a top level over the
    // objects' boxes within it (time_slices.hpp), so fast motion does not blow up every box.
    std::vector<std::unique_ptr<TopLevel>> slices_;
};

}  // namespace sweeptrace

#include "raytracer/accel/bvh_accel.hpp"

#include <variant>

#include "collision/bvh.hpp"
#include "raytracer/geometry/object_space.hpp"
#include "raytracer/geometry/shape.hpp"

namespace sweeptrace {

// An analytic shape test costs several box tests, a mesh instance far more, while the wide node
// tests 8 boxes at once: one object per leaf. Measured on scenes/spheres-field.json (bench):
// leaves of up to 4 gave native / Embree 0.83, leaves of 1 1.13.
constexpr int kTopLeafObjects = 1;

BvhAccel::BvhAccel(const Scene& scene, SimdPath path)
    : scene_(scene), path_(path), kernels_(&wide_kernels(path)), meshes_(scene.meshes.size()),
      mesh_views_(scene.meshes.size()) {
    std::vector<collision::Bounds3> boxes;
    std::vector<glm::vec3> centroids;
    std::vector<std::uint32_t> object_of;  // builder primitive -> object (empty objects skipped)
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        collision::Bounds3 local;
        if (const auto* instance = std::get_if<MeshInstance>(&object.shape)) {
            auto& mesh = meshes_[instance->mesh];
            if (!mesh) {
                mesh = std::make_unique<WideMeshBvh>(scene.meshes[instance->mesh].triangles, path);
                mesh_views_[instance->mesh] = mesh->view();
            }
            local = mesh->bounds();
        } else {
            local = object_space_bounds(object.shape);
        }
        if (local.empty()) continue;  // a mesh without triangles: nothing to hit
        moving_ = moving_ || object.motion.moving();
        const collision::Bounds3 world =
            object.motion.moving() ? motion_world_bounds(object.motion, local) : world_bounds(object.transform, local);
        boxes.push_back(world);
        centroids.push_back(0.5f * (world.lo + world.hi));
        object_of.push_back(i);
    }
    collision::BvhBuildOptions options;
    options.max_leaf_size = kTopLeafObjects;
    const collision::Bvh binary = collision::build_bvh(boxes, centroids, options);
    top_ = collapse_to_wide(binary, kTopLeafObjects);
    top_objects_.reserve(binary.prim_indices.size());
    for (std::uint32_t p : binary.prim_indices) {
        const Object& object = scene.objects[object_of[p]];
        const auto* sphere = std::get_if<collision::Sphere>(&object.shape);
        top_objects_.push_back(object_of[p]);
        const bool still_sphere = sphere && object.transform.identity && !object.motion.moving();
        top_spheres_.push_back(still_sphere ? *sphere : collision::Sphere{glm::vec3(0.0f), 0.0f});
    }
    // Each node's children that are one-slot leaves with such a sphere, for the node-level test.
    top_child_spheres_.assign(top_.nodes.size(), ChildSpheres{});
    for (std::size_t n = 0; n < top_.nodes.size(); ++n)
        for (int lane = 0; lane < kWideWidth; ++lane) {
            const std::uint32_t ref = top_.nodes[n].child[lane];
            if (!wide_ref::is_leaf(ref) || wide_ref::count(ref) != 1) continue;
            const collision::Sphere& s = top_spheres_[wide_ref::first(ref)];
            if (!(s.radius > 0.0f)) continue;
            top_child_spheres_[n].x[lane] = s.center.x;
            top_child_spheres_[n].y[lane] = s.center.y;
            top_child_spheres_[n].z[lane] = s.center.z;
            top_child_spheres_[n].r[lane] = s.radius;
        }
    view_ = TopLevelView{&scene_, &top_, top_objects_.data(), top_spheres_.data(), mesh_views_.data(),
                         top_child_spheres_.data()};
}

std::size_t BvhAccel::memory_bytes() const {
    std::size_t bytes = sizeof(*this) + top_.memory_bytes() + top_objects_.capacity() * sizeof(std::uint32_t) +
                        top_spheres_.capacity() * sizeof(collision::Sphere) +
                        top_child_spheres_.capacity() * sizeof(ChildSpheres) +
                        meshes_.capacity() * sizeof(meshes_[0]) + mesh_views_.capacity() * sizeof(WideMeshView);
    for (const auto& m : meshes_)
        if (m) bytes += sizeof(WideMeshBvh) + m->memory_bytes();
    return bytes;
}

std::size_t BvhAccel::triangle_count() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < meshes_.size(); ++i)
        if (meshes_[i]) n += scene_.meshes[i].triangles.triangle_count();
    return n;
}

double BvhAccel::mesh_sah_cost(std::size_t mesh) const { return meshes_[mesh] ? meshes_[mesh]->sah_cost() : 0.0; }

}  // namespace sweeptrace

#include "raytracer/accel/bvh_accel.hpp"

#include <variant>

#include "raytracer/accel/bvh_traversal.hpp"
#include "raytracer/accel/object_bounds.hpp"
#include "raytracer/accel/sah_cost.hpp"
#include "raytracer/geometry/intersect_object.hpp"
#include "raytracer/geometry/object_space.hpp"

namespace sweeptrace {

BvhAccel::BvhAccel(const Scene& scene) : scene_(scene), meshes_(scene.meshes.size()) {
    std::vector<collision::Bounds3> boxes;
    std::vector<glm::vec3> centroids;
    std::vector<std::uint32_t> object_of;  // builder primitive -> object (empty objects skipped)
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        collision::Bounds3 local;
        if (const auto* instance = std::get_if<MeshInstance>(&object.shape)) {
            auto& mesh = meshes_[instance->mesh];
            if (!mesh) mesh = std::make_unique<MeshBvh>(scene.meshes[instance->mesh].triangles);
            local = mesh->bounds();
        } else {
            local = object_space_bounds(object.shape);
        }
        if (local.empty()) continue;  // a mesh without triangles: nothing to hit
        const collision::Bounds3 world = world_bounds(object.transform, local);
        boxes.push_back(world);
        centroids.push_back(0.5f * (world.lo + world.hi));
        object_of.push_back(i);
    }
    collision::BvhBuildOptions options;
    options.max_leaf_size = 4;
    // An analytic shape test costs a few box tests; a mesh instance far more. Weighting the
    // primitive test above the node visit keeps expensive objects in small leaves.
    options.intersection_cost = 4.0f;
    top_ = collision::build_bvh(boxes, centroids, options);
    for (std::uint32_t& p : top_.prim_indices) p = object_of[p];
}

bool BvhAccel::intersect_one(std::uint32_t object_index, const collision::Ray& ray, SurfaceHit& hit) const {
    const Object& object = scene_.objects[object_index];
    if (const auto* instance = std::get_if<MeshInstance>(&object.shape)) {
        const ObjectRay local = to_object_space(object.transform, ray);
        collision::RayHit h;
        std::uint32_t triangle = 0;
        if (!meshes_[instance->mesh]->intersect(local.ray, h, triangle)) return false;
        mesh_hit_to_world(scene_.meshes[instance->mesh], object, object_index, triangle, h, local.t_shift, hit);
        return true;
    }
    return intersect_object(scene_, object_index, ray, hit);
}

bool BvhAccel::occluded_one(std::uint32_t object_index, const collision::Ray& ray) const {
    const Object& object = scene_.objects[object_index];
    if (const auto* instance = std::get_if<MeshInstance>(&object.shape))
        return meshes_[instance->mesh]->occluded(to_object_space(object.transform, ray).ray);
    SurfaceHit unused;
    return intersect_object(scene_, object_index, ray, unused);
}

bool BvhAccel::intersect(const collision::Ray& ray, SurfaceHit& hit) const {
    const TraversalRay r(ray);
    float tmax = ray.tmax;
    bool found = false;
    traverse(top_, r, ray.tmin, tmax, [&](std::uint32_t first, std::uint32_t count, float& t_limit) {
        for (std::uint32_t i = first; i < first + count; ++i) {
            collision::Ray clipped = ray;
            clipped.tmax = t_limit;
            if (intersect_one(top_.prim_indices[i], clipped, hit)) {
                // A transformed object's t = s + t_shift rounds once more; keep tmax monotone.
                t_limit = hit.t < t_limit ? hit.t : t_limit;
                found = true;
            }
        }
        return false;
    });
    return found;
}

bool BvhAccel::occluded(const collision::Ray& ray) const {
    const TraversalRay r(ray);
    float tmax = ray.tmax;
    bool blocked = false;
    traverse(top_, r, ray.tmin, tmax, [&](std::uint32_t first, std::uint32_t count, float&) {
        for (std::uint32_t i = first; i < first + count; ++i)
            if (occluded_one(top_.prim_indices[i], ray)) return blocked = true;
        return false;
    });
    return blocked;
}

std::size_t BvhAccel::memory_bytes() const {
    std::size_t bytes = sizeof(*this) + top_.memory_bytes() + meshes_.capacity() * sizeof(meshes_[0]);
    for (const auto& m : meshes_)
        if (m) bytes += sizeof(MeshBvh) + m->memory_bytes();
    return bytes;
}

std::size_t BvhAccel::triangle_count() const {
    std::size_t n = 0;
    for (std::size_t i = 0; i < meshes_.size(); ++i)
        if (meshes_[i]) n += scene_.meshes[i].triangles.triangle_count();
    return n;
}

double BvhAccel::mesh_sah_cost(std::size_t mesh) const {
    return meshes_[mesh] ? sah_cost(meshes_[mesh]->bvh()) : 0.0;
}

}  // namespace sweeptrace

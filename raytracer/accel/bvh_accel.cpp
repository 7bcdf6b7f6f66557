#include "raytracer/accel/bvh_accel.hpp"

#include <variant>

#include "collision/bvh.hpp"
#include "raytracer/accel/time_slices.hpp"
#include "raytracer/geometry/intersect_object.hpp"
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
    std::vector<collision::Bounds3> locals;  // per builder primitive: its object-space box
    std::vector<std::uint32_t> object_of;    // builder primitive -> object (empty objects skipped)
    bool moving = false;
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
        moving = moving || object.motion.moving();
        boxes.push_back(object.motion.moving() ? motion_world_bounds(object.motion, local)
                                               : world_bounds(object.transform, local));
        locals.push_back(local);
        object_of.push_back(i);
    }
    build_top(boxes, object_of, top_, top_objects_, top_spheres_, top_child_spheres_, view_);
    if (!moving) return;
    // Per primitive its box over each of the finest slices, then the slice count they call for.
    std::vector<std::vector<collision::Bounds3>> fine(boxes.size());  // empty for a still primitive
    std::vector<std::vector<collision::Bounds3>> fine_moving;
    for (std::size_t p = 0; p < boxes.size(); ++p) {
        const Object& object = scene.objects[object_of[p]];
        if (!object.motion.moving()) continue;
        for (int k = 0; k < kMaxTimeSlices; ++k)
            fine[p].push_back(motion_world_bounds(object.motion, locals[p], float(k) / kMaxTimeSlices,
                                                  float(k + 1) / kMaxTimeSlices));
        fine_moving.push_back(fine[p]);
    }
    const int slices = choose_time_slices(fine_moving);
    const int per = kMaxTimeSlices / slices;
    for (int k = 0; k < slices; ++k) {
        std::vector<collision::Bounds3> slice_boxes(boxes.size());
        for (std::size_t p = 0; p < boxes.size(); ++p) {
            if (fine[p].empty()) slice_boxes[p] = boxes[p];
            for (int j = 0; j < per && !fine[p].empty(); ++j)
                slice_boxes[p].extend(fine[p][static_cast<std::size_t>(k * per + j)]);
        }
        auto level = std::make_unique<TopLevel>();
        build_top(slice_boxes, object_of, level->tree, level->objects, level->spheres, level->child_spheres, level->view);
        for (std::uint32_t index : level->objects) level->swept.push_back(swept_sphere(scene.objects[index]));
        level->view.swept = level->swept.data();
        slices_.push_back(std::move(level));
    }
}

void BvhAccel::build_top(const std::vector<collision::Bounds3>& boxes, const std::vector<std::uint32_t>& object_of,
                         WideBvh& tree, std::vector<std::uint32_t>& objects, std::vector<collision::Sphere>& spheres,
                         std::vector<ChildSpheres>& child_spheres, TopLevelView& view) const {
    std::vector<glm::vec3> centroids;
    centroids.reserve(boxes.size());
    for (const collision::Bounds3& world : boxes) centroids.push_back(0.5f * (world.lo + world.hi));
    collision::BvhBuildOptions options;
    options.max_leaf_size = kTopLeafObjects;
    const collision::Bvh binary = collision::build_bvh(boxes, centroids, options);
    tree = collapse_to_wide(binary, kTopLeafObjects);
    objects.reserve(binary.prim_indices.size());
    for (std::uint32_t p : binary.prim_indices) {
        const Object& object = scene_.objects[object_of[p]];
        const auto* sphere = std::get_if<collision::Sphere>(&object.shape);
        objects.push_back(object_of[p]);
        const bool still_sphere = sphere && object.transform.identity && !object.motion.moving();
        spheres.push_back(still_sphere ? *sphere : collision::Sphere{glm::vec3(0.0f), 0.0f});
    }
    // Each node's children that are one-slot leaves with such a sphere, for the node-level test.
    child_spheres.assign(tree.nodes.size(), ChildSpheres{});
    for (std::size_t n = 0; n < tree.nodes.size(); ++n)
        for (int lane = 0; lane < kWideWidth; ++lane) {
            const std::uint32_t ref = tree.nodes[n].child[lane];
            if (!wide_ref::is_leaf(ref) || wide_ref::count(ref) != 1) continue;
            const collision::Sphere& s = spheres[wide_ref::first(ref)];
            if (!(s.radius > 0.0f)) continue;
            child_spheres[n].x[lane] = s.center.x;
            child_spheres[n].y[lane] = s.center.y;
            child_spheres[n].z[lane] = s.center.z;
            child_spheres[n].r[lane] = s.radius;
        }
    view = TopLevelView{&scene_, &tree, objects.data(), spheres.data(), mesh_views_.data(), child_spheres.data()};
}

std::size_t BvhAccel::TopLevel::memory_bytes() const {
    return sizeof(*this) + tree.memory_bytes() + objects.capacity() * sizeof(std::uint32_t) +
           spheres.capacity() * sizeof(collision::Sphere) + child_spheres.capacity() * sizeof(ChildSpheres) +
           swept.capacity() * sizeof(SweptSphere);
}

std::size_t BvhAccel::memory_bytes() const {
    std::size_t bytes = sizeof(*this) + top_.memory_bytes() + top_objects_.capacity() * sizeof(std::uint32_t) +
                        top_spheres_.capacity() * sizeof(collision::Sphere) +
                        top_child_spheres_.capacity() * sizeof(ChildSpheres) +
                        meshes_.capacity() * sizeof(meshes_[0]) + mesh_views_.capacity() * sizeof(WideMeshView) +
                        slices_.capacity() * sizeof(slices_[0]);
    for (const auto& level : slices_) bytes += level->memory_bytes();
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

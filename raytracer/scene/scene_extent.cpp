#include "raytracer/scene/scene_extent.hpp"

#include <cmath>
#include <string>
#include <variant>

// Object boxes come from the one place that knows each shape's extent, so this check and the
// accelerators agree on what a box is.
#include "raytracer/geometry/object_space.hpp"
#include "raytracer/geometry/shape.hpp"

namespace sweeptrace {

namespace {

using collision::Bounds3;

// The largest |coordinate| of the box, or infinity when any bound is not finite.
float reach(const Bounds3& b) {
    float m = 0.0f;
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a])) return INFINITY;
        m = std::fmax(m, std::fmax(std::fabs(b.lo[a]), std::fabs(b.hi[a])));
    }
    return m;
}

Bounds3 mesh_box(const Mesh& mesh) {
    Bounds3 b{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const glm::vec3& v : mesh.triangles.vertices) {
        b.lo = glm::min(b.lo, v);
        b.hi = glm::max(b.hi, v);
    }
    return b;
}

std::string reach_text(float r) {
    return std::isfinite(r) ? scene_json::format_number(r) : std::string("beyond the float range");
}

}  // namespace

void check_scene_extent(const Scene& scene, const scene_json::Node& root) {
    const std::string limit = scene_json::format_number(kMaxSceneCoordinate);
    const scene_json::Node camera = root.at("camera");
    for (const char* key : {"position", "look_at"}) {
        const glm::vec3 p = key[0] == 'p' ? scene.camera.position : scene.camera.look_at;
        const float r = reach(Bounds3{p, p});
        if (!(r <= kMaxSceneCoordinate))
            camera.at(key).fail("coordinates must lie within +-" + limit + ", got " + reach_text(r));
    }
    const scene_json::Node objects = root.at("objects");
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const auto* mesh = std::get_if<MeshInstance>(&o.shape);
        const Bounds3 local = mesh ? mesh_box(scene.meshes[mesh->mesh]) : object_space_bounds(o.shape);
        const float r_local = reach(local);
        if (!(r_local <= kMaxSceneCoordinate))
            objects.element(i).fail(std::string(mesh ? "the mesh's vertices" : "the shape's box") +
                                    " must lie within +-" + limit + " (larger ones overflow float in the BVH and the "
                                    "intersectors), it reaches " + reach_text(r_local));
        // A moving object over its whole shutter (every keyframe, and the poses between).
        const float r_world = reach(o.motion.moving() ? motion_world_bounds(o.motion, local) : world_bounds(o.transform, local));
        if (!(r_world <= kMaxSceneCoordinate))
            objects.element(i).fail("with its transform, its box must lie within +-" + limit +
                                    " (larger ones overflow float in the BVH and the intersectors), it reaches " +
                                    reach_text(r_world));
    }
}

}  // namespace sweeptrace

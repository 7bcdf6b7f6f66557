#pragma once
// An object's world box for decisions that need only a conservative extent (a directional
// light's share of the scene, whether an emitter faces anything): analytic shapes by their
// home's object-space box, mesh instances by the box of their mesh's vertices, both mapped to
// world with the transform's error bound (object_space.hpp, world_bounds). The acceleration
// structures box meshes by their own BVHs instead. A moving object's box holds it over the whole
// shutter (motion.hpp, motion_world_bounds).
#include <variant>
#include <vector>

#include "raytracer/geometry/object.hpp"
#include "raytracer/geometry/object_space.hpp"

namespace sweeptrace {

inline collision::Bounds3 object_world_bounds(const Object& obj, const std::vector<Mesh>& meshes) {
    collision::Bounds3 box = object_space_bounds(obj.shape);
    if (const auto* m = std::get_if<MeshInstance>(&obj.shape))
        for (const glm::vec3& v : meshes[m->mesh].triangles.vertices) box.extend(v);
    if (box.empty()) return box;
    return obj.motion.moving() ? motion_world_bounds(obj.motion, box) : world_bounds(obj.transform, box);
}

}  // namespace sweeptrace

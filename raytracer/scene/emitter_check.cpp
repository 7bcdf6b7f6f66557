#include "raytracer/scene/emitter_check.hpp"

#include <optional>

#include <glm/geometric.hpp>

#include "raytracer/geometry/object_world_bounds.hpp"

namespace sweeptrace {

namespace {

// The world plane of a flat shape's front (its home's front(), mapped by the transform), or
// nothing for shapes without one.
std::optional<FlatFront> world_front(const Object& obj) {
    return visit_shape(obj.shape, [&](auto home, const auto& g) -> std::optional<FlatFront> {
        using Home = decltype(home);
        if constexpr (requires { Home::front(g); }) {
            const FlatFront f = Home::front(g);
            return FlatFront{glm::vec3(obj.transform.to_world * glm::vec4(f.point, 1.0f)),
                             obj.transform.normal_to_world * f.normal};
        } else {
            return std::nullopt;
        }
    });
}

// True when some corner of `box` lies strictly in front of the plane.
bool in_front(const FlatFront& plane, const collision::Bounds3& box) {
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 c((k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y, (k & 4) ? box.hi.z : box.lo.z);
        if (glm::dot(c - plane.point, plane.normal) > 0.0f) return true;
    }
    return false;
}

}  // namespace

std::vector<std::string> emitters_facing_nothing(const Scene& scene) {
    std::vector<std::string> out;
    if (scene.objects.size() < 2) return out;
    std::vector<collision::Bounds3> boxes;
    for (const Object& obj : scene.objects) boxes.push_back(object_world_bounds(obj, scene.meshes));
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& obj = scene.objects[i];
        const Material& m = scene.materials[obj.material];
        if (m.two_sided_emission || !(m.emission.x > 0.0f || m.emission.y > 0.0f || m.emission.z > 0.0f)) continue;
        const std::optional<FlatFront> front = world_front(obj);
        if (!front) continue;
        bool faces_something = false;
        collision::Bounds3 others;
        for (std::size_t j = 0; j < scene.objects.size(); ++j) {
            if (j == i || boxes[j].empty()) continue;
            faces_something = faces_something || in_front(*front, boxes[j]);
            others.extend(boxes[j]);
        }
        if (others.empty()) continue;
        const glm::vec3 centre = 0.5f * (others.lo + others.hi);
        std::string what;
        if (!faces_something)
            what = "faces away from every other object and lights none of them";
        else if (!(glm::dot(centre - front->point, front->normal) > 0.0f) &&
                 !(glm::dot(scene.camera.position - front->point, front->normal) > 0.0f))
            what = "faces away from the camera and from the centre of the other objects' bounds (it lights only "
                   "what lies beyond the scene's middle, e.g. the ceiling right above a flipped ceiling light)";
        else
            continue;
        out.push_back(scene.source.string() + ": " + obj.name + ": one-sided emitter (material \"" + m.name + "\") " +
                      what + "; turn its front around (swap edge_u and edge_v, negate the disk's normal, reorder the "
                      "triangle) or set \"two_sided\": true");
    }
    return out;
}

}  // namespace sweeptrace

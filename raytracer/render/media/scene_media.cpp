#include "raytracer/render/media/scene_media.hpp"

#include <glm/geometric.hpp>

namespace sweeptrace {

SceneMedia::SceneMedia(const Scene& scene) : scene_(scene) {
    models_.reserve(scene.media.size());
    for (const Medium& m : scene.media) models_.emplace_back(m);
    active_ = uses_media(scene);
}

std::int32_t SceneMedia::after_crossing(std::uint32_t object, const glm::vec3& normal, const glm::vec3& dir,
                                        std::int32_t current) const {
    const MediumInterface& mi = scene_.objects[object].media;
    if (!mi.transition()) return current;
    return glm::dot(dir, normal) > 0.0f ? mi.outside : mi.inside;
}

bool SceneMedia::is_interface(const SurfaceHit& hit) const {
    return scene_.materials[scene_.objects[hit.object].material].type == Material::Type::Interface;
}

}  // namespace sweeptrace

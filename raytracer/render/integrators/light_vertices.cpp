#include "raytracer/render/integrators/light_vertices.hpp"

#include <glm/geometric.hpp>

namespace sweeptrace {

void LightVertices::clear() {
    photons_.clear();
    surfaces_.clear();
    textured_.clear();
}

void LightVertices::push(const PathVertex& v, std::int32_t front, std::int32_t back) {
    photons_.push_back({v.hit.point, v.wo, v.beta, v.hit.normal, v.light_mis});
    const auto side = [](std::int32_t m) { return static_cast<std::int16_t>(m); };  // media are < 2^15 (scene/medium.hpp)
    if (v.in_medium()) {
        surfaces_.push_back({glm::vec3(0.0f), glm::vec3(0.0f), static_cast<std::uint32_t>(v.medium), side(v.medium), side(v.medium)});
        return;
    }
    std::uint32_t material = v.material;
    if (v.has_textured) {
        material = kTextured | static_cast<std::uint32_t>(textured_.size());
        textured_.push_back(v.textured);
    }
    surfaces_.push_back({v.hit.shading_normal, v.hit.point_error, material, side(front), side(back)});
}

std::int32_t LightVertices::medium_toward(std::size_t i, const glm::vec3& dir) const {
    const Surface& s = surfaces_[i];
    return glm::dot(dir, photons_[i].normal) > 0.0f ? s.front : s.back;
}

void LightVertices::append(const LightVertices& other) {
    const auto base = static_cast<std::uint32_t>(textured_.size());
    photons_.insert(photons_.end(), other.photons_.begin(), other.photons_.end());
    for (Surface s : other.surfaces_) {
        if ((s.material & kTextured) != 0) s.material += base;
        surfaces_.push_back(s);
    }
    textured_.insert(textured_.end(), other.textured_.begin(), other.textured_.end());
}

SurfaceHit LightVertices::hit(std::size_t i) const {
    SurfaceHit h;
    h.point = photons_[i].point;
    h.normal = photons_[i].normal;
    h.shading_normal = surfaces_[i].shading_normal;
    h.point_error = surfaces_[i].point_error;
    return h;
}

const MaterialParameters& LightVertices::material(std::size_t i, const Scene& scene) const {
    const std::uint32_t m = surfaces_[i].material;
    return (m & kTextured) != 0 ? textured_[m & ~kTextured] : scene.materials[m];
}

}  // namespace sweeptrace

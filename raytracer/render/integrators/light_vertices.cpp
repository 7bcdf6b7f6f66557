#include "raytracer/render/integrators/light_vertices.hpp"

namespace sweeptrace {

void LightVertices::clear() {
    photons_.clear();
    surfaces_.clear();
    textured_.clear();
}

void LightVertices::push(const PathVertex& v) {
    photons_.push_back({v.hit.point, v.wo, v.beta, v.hit.normal, v.light_mis});
    std::uint32_t material = v.material;
    if (v.has_textured) {
        material = kTextured | static_cast<std::uint32_t>(textured_.size());
        textured_.push_back(v.textured);
    }
    surfaces_.push_back({v.hit.shading_normal, v.hit.point_error, material});
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

#pragma once
// One vertex of a camera or light subpath (bidirectional methods: bdpt.cpp), with the two
// densities the MIS weights of every connection strategy are built from (Veach 1997, §10.2;
// pbrt-v4's Vertex): pdf_own, the density with which the subpath that holds the vertex sampled
// it from its predecessor, and pdf_other, the density with which the other subpath's direction
// would have sampled it from its successor. Which of them is light-to-camera depends on the
// subpath: bidir_mis.hpp's gather_mis_path alone turns them into the path's order. Both are per unit area at the vertex (per unit solid angle for a
// light at infinity, whose "position" is its direction), and 0 where a delta lobe decided.
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

struct PathVertex {
    enum class Kind : std::uint8_t { Camera, Light, Surface };
    Kind kind = Kind::Surface;
    // Surface: the hit (its shading normal after any normal map). Light: point, error, outward
    // normal (the direction of travel at infinity), object and primitive of a surface light.
    // Camera: the lens point.
    SurfaceHit hit;
    glm::vec3 wo{0.0f};    // Surface: unit, toward the previous vertex of its own subpath
    glm::vec3 beta{1.0f};  // the subpath's throughput up to and including this vertex's arrival
    float pdf_own = 0.0f, pdf_other = 0.0f;
    // Light vertex of a light subpath: next event estimation's density of it from the subpath's
    // second vertex (per unit area; selection alone for a point; per solid angle at infinity).
    float pdf_nee = 0.0f;
    bool delta = false;  // the subpath left this vertex by a delta lobe
    // Light vertices:
    std::uint32_t light = 0;
    bool at_infinity = false, delta_position = false, delta_direction = false;
    // Surface: the material, textured at the hit when it reads a texture (`textured` then holds it).
    std::uint32_t material = 0;
    bool has_textured = false;
    MaterialParameters textured;

    const MaterialParameters& mat(const Scene& scene) const { return has_textured ? textured : scene.materials[material]; }
    // A point with a surface around it (its area density converts by a cosine).
    bool on_surface() const { return kind == Kind::Surface || (kind == Kind::Light && !delta_position && !at_infinity); }
    const glm::vec3& point() const { return hit.point; }
};

// A solid-angle density at `from` turned into the density per unit area at `to` (pbrt-v4's
// ConvertDensity): times |cos| at `to` / distance^2; unchanged toward a light at infinity.
inline float area_density(float pdf_solid_angle, const glm::vec3& from, const PathVertex& to) {
    if (to.at_infinity) return pdf_solid_angle;
    const glm::vec3 w = to.hit.point - from;
    const float d2 = glm::dot(w, w);
    if (!(d2 > 0.0f)) return 0.0f;
    const float c = to.on_surface() ? std::abs(glm::dot(to.hit.normal, w)) / std::sqrt(d2) : 1.0f;
    return pdf_solid_angle * c / d2;
}

}  // namespace sweeptrace

#pragma once
// One vertex of a camera or light subpath (bidirectional methods: bdpt.cpp), with the two
// densities the MIS weights of every connection strategy are built from (Veach 1997, §10.2;
// pbrt-v4's Vertex): pdf_own, the density with which the subpath that holds the vertex sampled
// it from its predecessor, and pdf_other, the density with which the other subpath's direction
// would have sampled it from its successor. Which of them is light-to-camera depends on the
// subpath: mis_window.hpp alone turns them into the path's order. Both are per unit area at the
// vertex (per unit solid angle for a light at infinity, whose "position" is its direction), and 0
// where a delta lobe decided. A medium vertex (participating media) is a fourth kind, its
// Henyey-Greenstein phase function in the place of the BSDF and no normal, so no cosine converts
// a density to it; a vertex reached by a free flight through a medium also has the flight's
// density in both of its own (render/media/subpath_flight.hpp: sigma_t T, or T at a surface).
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/render/integrators/bidir_mis.hpp"
#include "raytracer/render/media/subpath_flight.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// What a light subpath's vertex x_b (b >= 1) brings to the MIS weight of any connection or merge
// at it (mis_window.hpp), fixed once the walk reached it: its own density, its predecessor's and
// how a density there converts from solid angle at x_b, the subpath's tail before x_{b-1}
// (bidir_mis.hpp), and x_0's densities. 32 bytes: it travels with every stored photon.
struct LightVertexMis {
    float pdf_own = 0.0f;       // x_b sampled from x_{b-1} (per unit area)
    float prev_pdf_own = 0.0f;  // x_{b-1} from x_{b-2}; for b = 1 emission's density of x_0
    float prev_area = 0.0f;     // x_{b-1}'s density per unit area per unit solid angle at x_b (cos / d^2; 1 at infinity)
    MisTail below;              // the strategies before x_{b-1}, relative to strategy b - 1
    float emit0 = 0.0f, nee0 = 0.0f;  // x_0's densities (bidir_mis.hpp)
    std::uint16_t depth = 0;    // b
    std::uint8_t flags = 0;     // kDeltaPrev | kDeltaPrevPrev | kLightHittable | kMedium | kMediumPrev
    // kMedium: x_b is a medium vertex; kMediumPrev: x_{b-1} is.
    static constexpr std::uint8_t kDeltaPrev = 1, kDeltaPrevPrev = 2, kLightHittable = 4, kMedium = 8, kMediumPrev = 16;
};

struct PathVertex {
    enum class Kind : std::uint8_t { Camera, Light, Surface, Medium };
    Kind kind = Kind::Surface;
    // Surface: the hit (its shading normal after any normal map). Light: point, error, outward
    // normal (the direction of travel at infinity), object and primitive of a surface light.
    // Camera: the lens point. Medium: the point (error and normals 0, object LightSet::kNoObject).
    SurfaceHit hit;
    glm::vec3 wo{0.0f};    // Surface, Medium: unit, toward the previous vertex of its own subpath
    // Media: the medium the vertex sits in (Surface: the side its subpath arrived from; Light:
    // the side it emits into; -1 vacuum), the MIS transmittance of the segment from its
    // predecessor in its own subpath, and a medium vertex's extinction (subpath_flight.hpp).
    std::int32_t medium = -1;
    glm::vec3 mis_tr{1.0f};
    glm::vec3 sigma_t{0.0f};
    glm::vec3 beta{1.0f};  // the subpath's throughput up to and including this vertex's arrival
    float pdf_own = 0.0f, pdf_other = 0.0f;
    // Light subpath, b >= 1: its MIS quantities. Camera subpath, cam[j]: the tail after x_{s+2}
    // (s = k - j; bidir_mis.hpp), the strategies past cam[j - 2] relative to the one at it.
    LightVertexMis light_mis;
    MisTail above;
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
    bool in_medium() const { return kind == Kind::Medium; }
};

// The flight's density factor of `at` reached over a segment with MIS transmittance `mis_tr`
// (subpath_flight.hpp): 1 in vacuum.
inline float flight_density(const glm::vec3& mis_tr, const PathVertex& at) {
    return flight_density(mis_tr, at.sigma_t, at.in_medium());
}

// A solid-angle density at `from` turned into the density per unit area at a surface point `to`
// with unit normal `normal` (pbrt-v4's ConvertDensity): times |cos| at `to` / distance^2.
inline float area_density(float pdf_solid_angle, const glm::vec3& from, const glm::vec3& to, const glm::vec3& normal) {
    const glm::vec3 w = to - from;
    const float d2 = glm::dot(w, w);
    if (!(d2 > 0.0f)) return 0.0f;
    return pdf_solid_angle * (std::abs(glm::dot(normal, w)) / std::sqrt(d2)) / d2;
}

// The same toward a vertex: unchanged toward a light at infinity, no cosine at a point light.
inline float area_density(float pdf_solid_angle, const glm::vec3& from, const PathVertex& to) {
    if (to.at_infinity) return pdf_solid_angle;
    if (to.on_surface()) return area_density(pdf_solid_angle, from, to.hit.point, to.hit.normal);
    const glm::vec3 w = to.hit.point - from;
    const float d2 = glm::dot(w, w);
    return d2 > 0.0f ? pdf_solid_angle / d2 : 0.0f;
}

}  // namespace sweeptrace

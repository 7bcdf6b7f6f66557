#pragma once
// A light subpath's vertices as connections and merges read them after the walk (bdpt.cpp's
// sample, vcm.cpp's iteration): only the ones a technique can end at, the non-delta surface
// vertices x_b, b >= 1 (x_0 is joined to the camera during the walk; next event estimation draws
// its own). Stored as two flat arrays: the photon, 80 bytes, all a merge reads (the camera
// vertex's BSDF is the only one a merge evaluates, so the photon needs no material), and what a
// connection reads besides (the shading normal and point error of the hit, the material: an index
// into the scene's, or into the textured ones kept here when the material reads a texture, and
// the media on its two sides). A medium vertex (its photon's mis.flags has kMedium, its normal is
// 0) keeps its medium's index in the place of the material: connections evaluate its phase
// function; merges skip it (vcm merges on surfaces only, bidir_mis.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/render/integrators/path_vertex.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

struct Photon {
    glm::vec3 point;
    glm::vec3 wo;      // unit, toward the previous vertex (where the light came from)
    glm::vec3 beta;    // the light subpath's throughput on arrival (power)
    glm::vec3 normal;  // the unit geometric normal: merges keep to surfaces facing the same way
    LightVertexMis mis;
};
static_assert(sizeof(Photon) <= 80, "a photon is at most 80 bytes (issue 39)");

class LightVertices {
public:
    // What a stored vertex costs vcm in an iteration: its photon and surface here, and the grid's
    // pointer, slot and table share (photon_grid.hpp). For memory estimates (cli/memory_budget.cpp).
    static constexpr std::size_t kBytesPerVertex = sizeof(Photon) + 32 + sizeof(void*) + 2 * sizeof(std::uint32_t);

    void clear();
    // light[b] (b >= 1, a medium vertex or a surface vertex whose material is not a delta one),
    // its MIS quantities set; a surface's media on its normal's side and the other (-1 vacuum).
    void push(const PathVertex& v, std::int32_t front = -1, std::int32_t back = -1);
    // Appends another store's vertices (same scene).
    void append(const LightVertices& other);
    std::size_t size() const { return photons_.size(); }
    std::span<const Photon> photons() const { return photons_; }
    const Photon& photon(std::size_t i) const { return photons_[i]; }
    // Vertex i's hit (point, error, normals; no uv, object or primitive: no texture is read again).
    SurfaceHit hit(std::size_t i) const;
    const MaterialParameters& material(std::size_t i, const Scene& scene) const;  // a surface vertex's
    bool in_medium(std::size_t i) const { return (photons_[i].mis.flags & LightVertexMis::kMedium) != 0; }
    // The medium a ray from vertex i along `dir` starts in (-1 vacuum): a medium vertex's own, a
    // surface's on the side `dir` leaves to.
    std::int32_t medium_toward(std::size_t i, const glm::vec3& dir) const;
private:
    struct Surface {
        glm::vec3 shading_normal;
        glm::vec3 point_error;
        std::uint32_t material;  // into Scene::materials, or into textured_ with kTextured set; a medium vertex's medium
        std::int16_t front, back;  // the media on the normal's side and the other (-1 vacuum)
    };
    static_assert(sizeof(Surface) <= 32);
    static constexpr std::uint32_t kTextured = 0x80000000u;
    std::vector<Photon> photons_;
    std::vector<Surface> surfaces_;
    std::vector<MaterialParameters> textured_;
};

}  // namespace sweeptrace

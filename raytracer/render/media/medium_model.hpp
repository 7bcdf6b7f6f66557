#pragma once
// One medium of the scene (scene/medium.hpp), ready to be sampled: its coefficients at a point
// and the majorant segments along a ray. Both kinds share one interface, so delta and ratio
// tracking (tracking.hpp) are written once.
//
// The majorant is one number for all three channels, the largest extinction sigma_t of any
// channel (times the cell's largest density for grids): a collision then falls at the same place
// whichever channel is followed, ratio tracking bounds every channel at once, and chromatic media
// differ only in the collision's event probabilities (tracking.hpp, spectral MIS).
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "raytracer/render/media/majorant_grid.hpp"
#include "raytracer/scene/medium.hpp"

namespace sweeptrace {

// Whether `m` emits light anywhere: its emission counts times sigma_a (scene/medium.hpp).
inline bool medium_emits(const Medium& m) { return m.emission != glm::vec3(0.0f) && m.sigma_a != glm::vec3(0.0f); }

struct MediumPoint {
    glm::vec3 sigma_a{0.0f}, sigma_s{0.0f};
    glm::vec3 emission{0.0f};  // radiance emitted per unit sigma_a there
};

class MediumModel {
public:
    // Grids get a majorant grid of `majorant_res`^3 cells (16 as pbrt-v4; 1 is one global bound,
    // kept for the benchmark that measures what the finer grid saves).
    explicit MediumModel(const Medium& m, int majorant_res = 16);

    const Medium& medium() const { return *m_; }
    bool homogeneous() const { return m_->kind == Medium::Kind::Homogeneous; }
    bool emits() const { return emits_; }
    float g() const { return m_->g; }

    MediumPoint at(const glm::vec3& world) const;

    // Calls f(t0, t1, mu) for each stretch of the ray o + t d (unit d, world units) within
    // [tmin, tmax] on which the extinction of every channel is at most mu; stretches where the
    // medium is empty are left out. In order along the ray; stops (returning false) when f
    // returns false. tmax may be infinite for homogeneous media.
    template <class F>
    bool majorants(const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, F&& f) const;

    // The density lookup in grid space (the unit cube over [p0, p1]): trilinear between the
    // samples at voxel centres, 0 outside the grid's samples.
    float density(const glm::vec3& grid) const;

private:
    float sample(int x, int y, int z, const std::vector<float>& v) const;
    glm::vec3 to_grid(const glm::vec3& world) const;
    float lookup(const glm::vec3& grid, const std::vector<float>& v) const;

    const Medium* m_;
    float max_sigma_t_ = 0.0f;  // the largest channel of sigma_a + sigma_s
    bool emits_ = false;
    glm::mat4 to_grid_{1.0f};   // world -> grid space (the medium's transform, then [p0, p1] -> [0, 1]^3)
    MajorantGrid majorant_;
};

template <class F>
bool MediumModel::majorants(const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, F&& f) const {
    if (!(tmin < tmax) || max_sigma_t_ == 0.0f) return true;
    if (homogeneous()) return f(tmin, tmax, max_sigma_t_);
    // The grid's map is affine, so t is the same parameter in both spaces.
    const glm::vec3 og = glm::vec3(to_grid_ * glm::vec4(o, 1.0f));
    const glm::vec3 dg = glm::vec3(to_grid_ * glm::vec4(d, 0.0f));
    return majorant_.walk(og, dg, tmin, tmax, [&](float t0, float t1, float bound) {
        return bound == 0.0f || f(t0, t1, bound * max_sigma_t_);
    });
}

}  // namespace sweeptrace

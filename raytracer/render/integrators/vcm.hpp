#pragma once
// Vertex connection and merging (Georgiev, Křivánek, Davidovič, Slusallek 2012): bidirectional
// path tracing (bdpt.hpp, whose subpaths, strategies and splats this reuses) plus photon merging,
// so that light reaching a diffuse surface through a specular one (a caustic seen through water:
// light, specular, diffuse, specular, camera), which no connection strategy samples, converges.
//
// One iteration is one pass of the renderer, sample index i for every pixel:
//   1. the light pass: one light subpath per pixel, drawn from that pixel's sampler at index i
//      (the numbers bdpt's sample would draw), its t = 1 splats, kept per pixel;
//   2. its non-delta surface vertices (photons) go into a hashed grid (collision/hashed_grid.hpp,
//      cell keys compared in full, cells of side 2 r_i), in pixel order, then vertex order;
//   3. the camera pass: each pixel's camera subpath joined to its own pixel's light subpath by
//      bdpt's strategies, and merged at every non-delta camera vertex with every photon within r_i
//      of it (the cells' photons in their stored order), by the constant kernel 1 / (pi r_i^2).
// Every technique is weighted by vcm_mis.hpp (eta = pi r_i^2 N, N = the pixel count).
// Radius: r_i = r_1 (i + 1)^((alpha - 1) / 2), alpha = 0.75 (the paper's progressive schedule),
// so iteration i depends on nothing but (seed, i): a farm part [a, b) runs iterations a..b-1 and
// parts merge to the whole render bit for bit. r_1 = film.vcm_radius, by default half the median
// pixel footprint (the width a pixel covers where its centre ray meets the scene) over a fixed
// 16 x 16 grid of centre rays: one number per render and per farm part, computed once. Not a
// fraction of the scene's bounding sphere (SmallVCM's default): walls made of huge spheres
// (smallpt's, radius 1e5) or a vast ground make that radius hundreds of units and merging a blur
// of the whole room.
// Motion blur: a photon was traced at its own pixel's shutter time, so merging across pixels
// would mix times; with a moving object under an open shutter merging is off (bdpt's weights,
// eta = 0) and vcm renders what bdpt does.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "collision/hashed_grid.hpp"
#include "raytracer/render/integrators/bdpt.hpp"

namespace sweeptrace {

class VcmIntegrator {
public:
    static constexpr float kAlpha = 0.75f;
    static constexpr float kDefaultPixelFootprints = 0.5f;

    // `bdpt` is the renderer's, already set up for the scene; this sets its merge density per
    // iteration.
    VcmIntegrator(const Scene& scene, const Accel& accel, const CameraModel& camera, const LightSet& lights,
                  BdptIntegrator& bdpt, int max_depth);

    // r_1 for `scene` seen by `camera`: film.vcm_radius or the default above (the scene's
    // bounding-sphere radius x 0.003 where no centre ray meets anything).
    static float first_radius(const Scene& scene, const Accel& accel, const CameraModel& camera);
    // The median over a 16 x 16 grid of pixel centres of the width one pixel covers where its
    // centre ray meets the scene; 0 when no ray meets anything.
    static float median_pixel_footprint(const Scene& scene, const Accel& accel, const CameraModel& camera);
    // r_i of iteration i (0-based: r_0 = r_1 of the paper's 1-based numbering).
    float radius(int iteration) const;

    // Single-threaded, before the light pass of iteration i.
    void begin_iteration(int iteration);
    // The light pass: pixel's light subpath (any thread; one call per pixel), its splats appended.
    void trace_light(std::size_t pixel, float time, PixelSampler& sampler, std::uint64_t& rays,
                     std::vector<Splat>& splats);
    // Single-threaded, after the light pass: the photons into the grid.
    void build_grid();
    // The camera pass: pixel's camera sample, every connection and merge (any thread). With
    // `features`, its camera subpath's (render --aovs, sample_features.hpp).
    glm::vec3 sample(std::size_t pixel, float x, float y, const glm::vec2& lens, float time, PixelSampler& sampler,
                     std::uint64_t& rays, SampleFeatures* features = nullptr) const;

    std::size_t photon_count() const { return photons_.size(); }

private:
    struct Photon {
        glm::vec3 point;
        std::uint32_t pixel;  // whose light subpath
        std::uint32_t index;  // its vertex there (>= 1)
    };
    glm::vec3 merge(const std::vector<PathVertex>& cam, int j) const;

    const Scene& scene_;
    const LightSet& lights_;
    BdptIntegrator& bdpt_;
    int max_depth_;
    float r1_;
    bool merging_ = true;
    float radius_ = 0.0f, eta_ = 0.0f;
    std::vector<std::vector<PathVertex>> paths_;  // the iteration's light subpaths, per pixel
    std::vector<Photon> photons_;
    collision::HashedGrid<> grid_{1.0f};
};

}  // namespace sweeptrace

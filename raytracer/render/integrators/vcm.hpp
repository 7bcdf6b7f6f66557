#pragma once
// Vertex connection and merging (Georgiev, Křivánek, Davidovič, Slusallek 2012): bidirectional
// path tracing (bdpt.hpp, whose subpaths, strategies and splats this reuses) plus photon merging,
// so that light reaching a diffuse surface through a specular one (a caustic seen through water:
// light, specular, diffuse, specular, camera), which no connection strategy samples, converges.
//
// One iteration is one pass of the renderer, sample index i for every pixel:
//   1. the light pass: one light subpath per pixel, drawn from that pixel's sampler at index i
//      (the numbers bdpt's sample would draw), its t = 1 splats; its non-delta surface vertices
//      (light_vertices.hpp: an 80-byte photon and what a connection reads besides) kept in one
//      flat store per tile of the renderer, in pixel order, then vertex order, each pixel's run
//      noted;
//   2. the photons, tile by tile, are sorted into a grid of cells of side 2 r_i (photon_grid.hpp:
//      a counting sort of pointers to them);
//   3. the camera pass: each pixel's camera subpath joined to its own pixel's light vertices by
//      bdpt's strategies, and merged at every non-delta camera vertex with every photon within r_i
//      of it on a surface facing the same way (the cells' photons in their sorted order), by the
//      constant kernel 1 / (pi r_i^2).
// Every technique is weighted by bidir_mis.hpp (eta = pi r_i^2 N, N = the pixel count), from the
// window around it and the tails its vertices carry (mis_window.hpp): a merge evaluates the camera
// vertex's BSDF once and costs the same at any depth (SmallVCM's recursive MIS).
// Radius: r_i = r_1 (i + 1)^((alpha - 1) / 2), alpha = 0.75 (the paper's progressive schedule),
// held between the rounding of the scene's largest coordinate and the scene's size (and where
// eta stays a normal, finite float), so no r_1 the loader lets through makes it 0 or infinite;
// iteration i depends on nothing but (seed, i): a farm part [a, b) runs iterations a..b-1 and
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

#include "raytracer/render/integrators/bdpt.hpp"
#include "raytracer/render/integrators/photon_grid.hpp"

namespace sweeptrace {

class VcmIntegrator {
public:
    static constexpr float kAlpha = 0.75f;
    static constexpr float kDefaultPixelFootprints = 0.5f;

    // `bdpt` is the renderer's, already set up for the scene; its camera subpaths are weighted
    // with the iteration's merge density.
    VcmIntegrator(const Scene& scene, const Accel& accel, const CameraModel& camera,
                  const BdptIntegrator& bdpt, int max_depth);

    // r_1 for `scene` seen by `camera`: film.vcm_radius or the default above (the scene's
    // bounding-sphere radius x 0.003 where no centre ray meets anything).
    static float first_radius(const Scene& scene, const Accel& accel, const CameraModel& camera);
    // The median over a 16 x 16 grid of pixel centres of the width one pixel covers where its
    // centre ray meets the scene; 0 when no ray meets anything.
    static float median_pixel_footprint(const Scene& scene, const Accel& accel, const CameraModel& camera);
    // r_i of iteration i (0-based: r_0 = r_1 of the paper's 1-based numbering), finite and > 0.
    float radius(int iteration) const;
    // eta = pi r_i^2 N of iteration i, finite and > 0 (merging on or off).
    float merge_density(int iteration) const;

    // Single-threaded, before the light pass of iteration i, with the renderer's tile count.
    void begin_iteration(int iteration, int tiles);
    // The light pass: pixel's light subpath (one call per pixel), its splats appended; then
    // finish_tile once per tile. A tile's calls, its finish_tile last, come from one thread with no
    // other tile's in between (the thread's scratch store collects the tile's vertices).
    void trace_light(int tile, std::size_t pixel, float time, PixelSampler& sampler, std::uint64_t& rays,
                     std::vector<Splat>& splats);
    void finish_tile(int tile);
    // From one thread, after the light pass: the photons into the grid (which sorts in parallel).
    void build_grid();
    // The camera pass: pixel's camera sample, every connection and merge (any thread). With
    // `features`, its camera subpath's (render --aovs, sample_features.hpp).
    glm::vec3 sample(std::size_t pixel, float x, float y, const glm::vec2& lens, float time, PixelSampler& sampler,
                     std::uint64_t& rays, SampleFeatures* features = nullptr) const;

private:
    glm::vec3 merge(const std::vector<PathVertex>& cam, int j) const;

    // Where a pixel's light vertices are: light_[tile], [first, first + count).
    struct PixelRun {
        std::uint32_t tile = 0, first = 0, count = 0;
    };

    const Scene& scene_;
    const BdptIntegrator& bdpt_;
    int max_depth_;
    float r1_;
    float r_min_ = 0.0f, r_max_ = 0.0f;  // the schedule's bounds (the constructor says why)
    bool merging_ = true;
    float radius_ = 0.0f, eta_ = 0.0f;
    std::size_t pixels_;
    std::vector<LightVertices> light_;  // the iteration's light vertices, per tile
    std::vector<PixelRun> runs_;        // per pixel
    PhotonGrid grid_;
};

}  // namespace sweeptrace

#pragma once
// Bidirectional path tracing (Veach 1997, ch. 10; pbrt-v4's bdpt as the model): per camera
// sample, a camera subpath and a light subpath, and every way of joining them into a path of at
// most max_depth vertices after the camera:
//   s = 0: the camera subpath finds an emitter (or escapes to a light at infinity);
//   s = 1: next event estimation from a camera vertex (LightSet::sample, the path tracer's NEE);
//   s >= 2, t >= 2: a shadow ray between a light vertex and a camera vertex;
//   t = 1: a light vertex joined to a point on the lens (light tracing), landing on whatever
//          pixel it projects to: a splat, returned to the renderer, which adds the splats of a
//          pass in a fixed order (render/renderer.cpp) so the image is the same at any thread
//          count and any farm split.
// Weighted by the power heuristic over all strategies (bidir_mis.hpp); delta lobes and delta
// lights as pbrt does. Both subpaths see the scene at the camera sample's time. Light subpath
// throughputs carry power: refraction's 1/eta^2 is undone there (importance_refraction_scale)
// and shading normals get pbrt's adjoint correction |wo.ns||wi.ng| / (|wo.ng||wi.ns|).
// The surface emitters' and camera's densities are render/lights/light_emission.cpp's and
// CameraModel::direction_pdf; the pixel filter's weights for splats are f(dx) f(dy) / (int f)^2,
// what a camera sample of that pixel estimates (film_splats.hpp, where the renderer spreads them).
// Not done here: path guiding, film.clamp_indirect (the path tracer's firefly guard).
#include <atomic>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raytracer/accel/accel.hpp"
#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/camera.hpp"
#include "raytracer/render/film/film_splats.hpp"
#include "raytracer/render/integrators/bidir_mis.hpp"
#include "raytracer/render/integrators/light_vertices.hpp"
#include "raytracer/render/integrators/path_vertex.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/media/scene_media.hpp"
#include "raytracer/render/media/subpath_flight.hpp"
#include "raytracer/render/planted_defect.hpp"
#include "raytracer/render/sampling/roulette.hpp"
#include "raytracer/render/film/sample_features.hpp"
#include "raytracer/render/sampling/sampler.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

class BdptIntegrator {
public:
    BdptIntegrator(const Scene& scene, const Accel& accel, const LightSet& lights, const CameraModel& camera,
                   int max_depth, PlantedDefect defect, RoulettePolicy roulette = RoulettePolicy::adaptive(),
                   bool light_tracing_only = false);

    // One camera sample at film position (x, y) with lens sample `lens` and shutter fraction
    // `time`: returns what the strategies with t >= 2 bring to its pixel (the caller applies the
    // filter sample's weight, as for the path tracer) and appends the t = 1 splats to `splats`.
    // With `features`, the camera subpath's features go there (render --aovs,
    // sample_features.hpp; zeros under light tracing alone, which has no camera subpath).
    glm::vec3 sample(float x, float y, const glm::vec2& lens, float time, PixelSampler& sampler, std::uint64_t& rays,
                     std::vector<Splat>& splats, SampleFeatures* features = nullptr) const;

    // The two halves of sample() for vcm.cpp, which traces every light subpath of an iteration
    // before any camera subpath: the light subpath with its t = 1 splats, its vertices that
    // connect appended to `light` (light_vertices.hpp), and the camera subpath (into `cam`) joined
    // to the light subpath whose vertices are light's [first, first + count) by every strategy with
    // t >= 2, returning what sample() returns. `merge_eta` (bidir_mis.hpp: eta = pi r^2 N) > 0 puts
    // the merges into every strategy's weight, the light subpath's splats' too; 0 gives bdpt's.
    void light_subpath(float time, PixelSampler& sampler, std::uint64_t& rays, float merge_eta, LightVertices& light,
                       std::vector<Splat>& splats) const;
    glm::vec3 camera_subpath(float x, float y, const glm::vec2& lens, float time, PixelSampler& sampler,
                             std::uint64_t& rays, const LightVertices& light, std::size_t first, std::size_t count,
                             float merge_eta, std::vector<PathVertex>& cam, SampleFeatures* features = nullptr) const;
    // The planted defect's form in the MIS weights (bidir_mis.hpp).
    MisDefect mis_defect() const;
    // The render's cancel flag: once set, a sample's strategy loops stop where they are (at depth
    // 1024 one sample joins ~10^6 vertex pairs, over a second), and the renderer drops the pass
    // the cut samples belong to, so no cut sample reaches an image.
    void set_cancel(const std::atomic<bool>* flag) { cancel_ = flag; }
    bool cancelled() const { return cancel_ != nullptr && cancel_->load(std::memory_order_relaxed); }

private:
    struct Subpaths;
    // The camera subpath; `found` takes what the walk itself finds at full or its own weight:
    // escaped rays (s = 0 at infinity) and the emission of media along its flights.
    void camera_walk(float x, float y, const glm::vec2& lens, float time, PixelSampler& sampler, std::uint64_t& rays,
                     Subpaths& sp, glm::vec3& found) const;
    void light_walk(float time, PixelSampler& sampler, std::uint64_t& rays, Subpaths& sp) const;
    glm::vec3 connections(Subpaths& sp, const LightVertices& light, std::size_t first, std::size_t count, float time,
                          PixelSampler& sampler, std::uint64_t& rays) const;
    void store_light_vertices(const Subpaths& sp, LightVertices& out) const;
    bool next_vertex(const collision::Ray& ray, std::int32_t medium, float time, Rng& rng, std::uint64_t& rays,
                     glm::vec3& beta, PathVertex& v, glm::vec3* emitted = nullptr) const;
    bool light_roulette(PixelSampler& sampler, int b, glm::vec3& beta, float beta_start) const;
    glm::vec3 escaped_radiance(const Subpaths& sp, const glm::vec3& dir, const glm::vec3& beta, float pdf,
                               const glm::vec3& mis_tr) const;
    glm::vec3 emitter_hit(Subpaths& sp, int j) const;
    glm::vec3 next_event(Subpaths& sp, int j, float time, PixelSampler& sampler, std::uint64_t& rays) const;
    glm::vec3 connect(Subpaths& sp, const LightVertices& light, std::size_t i, int t, float time,
                      std::uint64_t& rays) const;
    void light_to_camera(Subpaths& sp, int s, float time, PixelSampler& sampler, std::uint64_t& rays,
                         std::vector<Splat>& splats) const;
    bool blocked(const collision::Ray& ray, float time) const;
    // With media: the transmittance of a joining ray from a vertex (segment_transmittance, starting in
    // `medium`); in vacuum the visibility test.
    template <class Next>
    SegmentTransmittance joined(const collision::Ray& ray, std::int32_t medium, float time, Rng& rng,
                                std::uint64_t& rays, Next&& next) const;
    // A vertex's scattering toward wi: its BSDF, or at a medium vertex its phase function.
    BsdfEvalBoth eval_at(const PathVertex& v, const glm::vec3& wi) const;
    // The medium a ray from v along dir starts in.
    std::int32_t medium_leaving(const PathVertex& v, const glm::vec3& dir) const;
    glm::vec3 extinction(std::int32_t medium, const glm::vec3& p) const {
        const MediumPoint mp = media_.model(medium).at(p);
        return mp.sigma_a + mp.sigma_s;
    }
    float weight(const MisPath& path, int s, float merge_eta) const;

    const Scene& scene_;
    const Accel& accel_;
    const LightSet& lights_;
    const CameraModel& camera_;
    int max_depth_;
    PlantedDefect defect_;
    RoulettePolicy roulette_;
    bool light_tracing_only_;  // Sampling::LightTracing: t = 1 alone, at full weight
    const std::atomic<bool>* cancel_ = nullptr;
    bool moving_ = false;
    float filter_radius_;
    std::vector<std::uint32_t> infinite_lights_;  // found by escaping rays (suns, the environment)
    SceneMedia media_;                            // inactive in vacuum: the walks trace surfaces alone
    // With media, per light: the medium a point or spot light emits into, found once
    // (light_media() in bdpt.cpp), or kProbeEachSample where each light subpath finds it.
    static constexpr std::int32_t kProbeEachSample = -2;
    std::vector<std::int32_t> light_medium_;
};

}  // namespace sweeptrace

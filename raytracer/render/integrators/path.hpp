#pragma once
// Unidirectional path tracing: the radiance arriving along one camera ray.
//
// At every path vertex, light is gathered two ways, combined by multiple importance sampling
// with the power heuristic (Veach 1997, ch. 9):
//   - next event estimation: a point on a light (LightSet), a shadow ray, weighted against the
//     density with which the BSDF would have sampled that direction;
//   - BSDF sampling: the next vertex, if emissive, contributes weighted against the density with
//     which NEE from the previous vertex would have sampled it.
// Delta lobes (mirror, glass) take no NEE and give the BSDF-sampled ray full weight; the camera
// ray, and escaped rays when the background is no light (scene_lights.cpp), too. Delta lights (point, spot,
// a directional light without a diameter) come only from NEE, at full weight; a sun with an
// angular diameter and an emitting background (render/lights/background_light.hpp) are found by escaped
// rays too (LightSet::escaped_radiance, MIS weighted). Sampling::BsdfOnly turns NEE
// off and gives every emitter hit full weight: an independent estimator of the same integral.
//
// Depth: max_depth counts path vertices after the camera, the emitting vertex included, so
// max_depth = 1 shows only emitters (and the background) seen directly. Both strategies stop at
// the same path length, so NeeMis and BsdfOnly estimate exactly the same truncated sum.
// Russian roulette as RoulettePolicy (roulette.hpp) states it. Each decision takes its numbers
// from the sampler's fixed dimension layout (sample_dim in sampler.hpp). With path guiding the
// throughput roulette looks at is the one BSDF sampling would have given (each guided vertex's
// mixture / BSDF density ratio, never below 1, multiplied in): any continuation probability in
// (0, 1] is unbiased, and this one does not end the guided paths that head for a light just
// because their density was high.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "collision/ray.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/render/guiding/guiding_sd_tree.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/media/scene_media.hpp"
#include "raytracer/render/film/path_forensics.hpp"
#include "raytracer/render/planted_defect.hpp"
#include "raytracer/render/sampling/roulette.hpp"
#include "raytracer/render/film/sample_features.hpp"
#include "raytracer/render/sampling/sampler.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

class PathIntegrator {
public:
    PathIntegrator(const Scene& scene, const Accel& accel, const LightSet& lights, int max_depth, Sampling sampling,
                   PlantedDefect defect, RoulettePolicy roulette = RoulettePolicy::adaptive());

    // `ray` must have a unit direction. Adds every ray traced to `rays`. With `records`, what
    // the path teaches the guide is appended there (guiding_path_recorder.hpp). The whole path,
    // shadow rays included, sees the scene at shutter fraction `time` (geometry/motion.hpp;
    // ignored when nothing moves). With `tally`, every contribution is also recorded there with
    // its path type (path_forensics.hpp); nothing else changes. With `features`, the path's
    // vertices are shown to it (render --aovs, sample_features.hpp); nothing else changes.
    glm::vec3 radiance(collision::Ray ray, PixelSampler& sampler, std::uint64_t& rays,
                       std::vector<GuideRecord>* records = nullptr, float time = 0.0f, PathTally* tally = nullptr,
                       FeatureRecord* features = nullptr) const;

    // Path guiding (guiding_sampler.hpp): at guided vertices where `guide` has learned something,
    // BSDF directions come from the BSDF + guide mixture, and its density is the BSDF strategy's
    // in MIS. The guide must not change during a radiance() call. nullptr: no guiding.
    void set_guide(const GuidingSdTree* guide) { guide_ = guide; }

private:
    collision::Ray continue_ray(const SurfaceHit& hit, const glm::vec3& dir) const;
    collision::Ray shadow_ray(const SurfaceHit& hit, const LightSample& ls) const;
    // A medium vertex as the start of a shadow ray: a point with no error bound, left unmoved.
    static SurfaceHit point_hit(const glm::vec3& p, const glm::vec3& toward);
    // The transmittance from `from` (in `medium` toward the light) to the light sample, through
    // interfaces and media (render/media/scene_media.hpp); zero when something opaque blocks it.
    glm::vec3 medium_shadow(const SurfaceHit& from, const LightSample& ls, std::int32_t medium, float time, Rng& rng,
                            std::uint64_t& rays) const;
    // The tag of the path's own random stream for the media (PixelSampler::stream).
    static constexpr std::uint64_t kMediumStream = 1;

    const Scene& scene_;
    const Accel& accel_;
    const LightSet& lights_;
    int max_depth_;
    Sampling sampling_;
    PlantedDefect defect_;
    RoulettePolicy roulette_;
    const GuidingSdTree* guide_ = nullptr;
    bool moving_ = false;  // the camera has a shutter and some object moves: queries take the time
    SceneMedia media_;
};

}  // namespace sweeptrace

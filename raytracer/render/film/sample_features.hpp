#pragma once
// The features a camera sample records for `render --aovs` (image/feature_sums.hpp sums them):
// albedo, shading normal and position at the first vertex of its camera path that is not
// specular, followed through delta bounces (mirrors, smooth glass) as OpenImageDenoise's guide
// images and pbrt-v4's gbuffer film define them, so a mirror shows the normals and albedo of what
// it reflects. Every integrator records the same quantity: the path tracer from its path, bdpt
// and vcm from their camera subpaths (features_of_subpath).
//
// The first non-specular vertex is the first that does not scatter (an emitter) or whose material
// is not a delta one (bsdf.hpp, is_delta). There:
//   albedo    the material's reflectance colour, no throughput of the delta bounces before it:
//             diffuse (and coated diffuse: its base) albedo; metal albedo (its tint); conductor
//             albedo x the Fresnel reflectance at normal incidence of its eta + i k; rough
//             dielectric albedo (its transmission tint); a surface that only emits (an
//             emissive material) its emitted radiance toward the ray (OpenImageDenoise's
//             suggestion for lights); all clamped to [0, 1] per channel, as OpenImageDenoise's
//             albedo guide is;
//   normal    the world-space shading normal (after normal and bump maps), on the arriving
//             ray's side of the surface (the frame the BSDF shades in);
//   position  the point in camera space (CameraModel::camera_space): z is the depth.
// A path that never reaches such a vertex (it escapes, is absorbed, or ends at max_depth or by
// Russian roulette on a delta vertex) records a miss: all three zero.
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/image/feature_sums.hpp"
#include "raytracer/render/camera.hpp"
#include "raytracer/render/integrators/path_vertex.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// Whether a camera path's features are taken at a vertex of material `m`.
bool records_features(const MaterialParameters& m);

// The features at `hit` of material `m` (textured, as the integrator shades it), reached by a
// ray arriving from direction `wo` (unit, pointing away from the surface).
SampleFeatures features_at(const MaterialParameters& m, const SurfaceHit& hit, const glm::vec3& wo, const CameraModel& camera);

// One camera path's features, as the integrator meets its vertices in order: the first vertex
// that records_features fills them, later ones change nothing; none, a miss (zeros).
class FeatureRecord {
public:
    explicit FeatureRecord(const CameraModel& camera) : camera_(camera) {}
    void at_vertex(const MaterialParameters& m, const SurfaceHit& hit, const glm::vec3& wo) {
        if (done_ || !records_features(m)) return;
        features_ = features_at(m, hit, wo, camera_);
        done_ = true;
    }
    const SampleFeatures& features() const { return features_; }

private:
    const CameraModel& camera_;
    SampleFeatures features_;
    bool done_ = false;
};

// bdpt, vcm: the features of camera subpath `cam` (cam[0] the lens, then surface vertices).
SampleFeatures features_of_subpath(const Scene& scene, const std::vector<PathVertex>& cam, const CameraModel& camera);

}  // namespace sweeptrace

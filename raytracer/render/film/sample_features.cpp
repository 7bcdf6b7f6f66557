#include "raytracer/render/film/sample_features.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"

namespace sweeptrace {

namespace {

// A conductor's reflectance at normal incidence, ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2) per
// channel: what it reflects of light arriving head on.
glm::vec3 conductor_f0(const MaterialParameters& m) {
    const glm::vec3 e = m.eta, k2 = m.k * m.k;
    return ((e - 1.0f) * (e - 1.0f) + k2) / ((e + 1.0f) * (e + 1.0f) + k2);
}

glm::vec3 feature_albedo(const MaterialParameters& m, const SurfaceHit& hit, const glm::vec3& wo) {
    switch (m.type) {
        case MaterialParameters::Type::Emissive: return emitted_radiance(m, hit.normal, wo);  // clamped by features_at
        case MaterialParameters::Type::Conductor: return m.albedo * conductor_f0(m);
        case MaterialParameters::Type::Diffuse:
        case MaterialParameters::Type::Metal:
        case MaterialParameters::Type::Dielectric:
        case MaterialParameters::Type::ThinDielectric:
        case MaterialParameters::Type::RoughDielectric:
        case MaterialParameters::Type::CoatedDiffuse: return m.albedo;
        case MaterialParameters::Type::Interface: return glm::vec3(0.0f);  // never a vertex: rays pass through
    }
    return m.albedo;
}

}  // namespace

bool records_features(const MaterialParameters& m) { return !scatters(m) || !is_delta(m); }

SampleFeatures features_at(const MaterialParameters& m, const SurfaceHit& hit, const glm::vec3& wo, const CameraModel& camera) {
    SampleFeatures f;
    // In [0, 1] per channel, as OpenImageDenoise's albedo guide is (a texture's HDR texel or an
    // emitter's radiance would be above): the feature sums are sized for that range.
    f.albedo = glm::clamp(feature_albedo(m, hit, wo), 0.0f, 1.0f);
    // Turned to the arriving ray's side of the surface as make_shading_context turns it (by the
    // geometric normal), so the feature is the normal the BSDF shades with.
    f.normal = glm::dot(wo, hit.normal) >= 0.0f ? hit.shading_normal : -hit.shading_normal;
    f.position = camera.camera_space(hit.point);
    return f;
}

SampleFeatures features_of_subpath(const Scene& scene, const std::vector<PathVertex>& cam, const CameraModel& camera) {
    FeatureRecord record(camera);
    // Surfaces only, as the path tracer records them: a medium vertex has no material.
    for (std::size_t j = 1; j < cam.size(); ++j)
        if (!cam[j].in_medium()) record.at_vertex(cam[j].mat(scene), cam[j].hit, cam[j].wo);
    return record.features();
}

}  // namespace sweeptrace

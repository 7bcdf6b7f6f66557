#include "raytracer/render/sample_features.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "raytracer/render/bsdf.hpp"

namespace sweeptrace {

namespace {

// A conductor's reflectance at normal incidence, ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2) per
// channel: what it reflects of light arriving head on.
glm::vec3 conductor_f0(const Material& m) {
    const glm::vec3 e = m.eta, k2 = m.k * m.k;
    return ((e - 1.0f) * (e - 1.0f) + k2) / ((e + 1.0f) * (e + 1.0f) + k2);
}

glm::vec3 feature_albedo(const Material& m, const SurfaceHit& hit, const glm::vec3& wo) {
    switch (m.type) {
        case Material::Type::Emissive: return glm::clamp(emitted_radiance(m, hit.normal, wo), 0.0f, 1.0f);
        case Material::Type::Conductor: return m.albedo * conductor_f0(m);
        case Material::Type::Diffuse:
        case Material::Type::Metal:
        case Material::Type::Dielectric:
        case Material::Type::ThinDielectric:
        case Material::Type::RoughDielectric:
        case Material::Type::CoatedDiffuse: return m.albedo;
    }
    return m.albedo;
}

}  // namespace

bool records_features(const Material& m) { return !scatters(m) || !is_delta(m); }

SampleFeatures features_at(const Material& m, const SurfaceHit& hit, const glm::vec3& wo, const CameraModel& camera) {
    SampleFeatures f;
    f.albedo = feature_albedo(m, hit, wo);
    // Turned to the arriving ray's side of the surface as make_shading_context turns it (by the
    // geometric normal), so the feature is the normal the BSDF shades with.
    f.normal = glm::dot(wo, hit.normal) >= 0.0f ? hit.shading_normal : -hit.shading_normal;
    f.position = camera.camera_space(hit.point);
    return f;
}

SampleFeatures features_of_subpath(const Scene& scene, const std::vector<PathVertex>& cam, const CameraModel& camera) {
    FeatureRecord record(camera);
    for (std::size_t j = 1; j < cam.size(); ++j) record.at_vertex(cam[j].mat(scene), cam[j].hit, cam[j].wo);
    return record.features();
}

}  // namespace sweeptrace

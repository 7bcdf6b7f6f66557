// LightSet's emission sampling and its densities (lights.hpp): what light tracing and
// bidirectional path tracing (render/integrators/bdpt.cpp) start their light subpaths from, and
// what their MIS weights ask about a light point a camera path found. Each density here is the
// one sample_emission draws with: test_render_light_emission.cpp checks both against each other.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

namespace {

// Nanson's formula, as lights.cpp states it: the world density of an object-area sample.
float object_area_density(const ShapeLight& l, const glm::vec3& n) {
    return l.area_pdf * glm::length(glm::transpose(l.linear) * n) * l.inv_abs_det;
}

// The area density of a light's surface point with world normal n, as sample_area draws it.
float surface_area_density(const ShapeLight& l, const glm::vec3& n) {
    return l.strategy == ShapeLight::Strategy::ObjectArea ? object_area_density(l, n) : l.area_pdf;
}

}  // namespace

std::uint32_t LightSet::light_of_sample(float u_select) const {
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u_select);
    return static_cast<std::uint32_t>(std::min<std::ptrdiff_t>(it - cdf_.begin(), std::ptrdiff_t(cdf_.size()) - 1));
}

float LightSet::light_selection(std::uint32_t light) const {
    if (light < lights_.size()) return lights_[light].probability;
    const std::size_t k = light - lights_.size();
    return k < scene_lights_.size() ? scene_lights_[k].probability : background_probability_;
}

bool LightSet::light_is_delta_position(std::uint32_t light) const {
    if (light < lights_.size()) return false;
    const std::size_t k = light - lights_.size();
    return k < scene_lights_.size() && scene_lights_[k].light->type != SceneLight::Type::Directional;
}

glm::vec3 LightSet::delta_light_position(std::uint32_t light) const {
    return scene_lights_[light - lights_.size()].light->position;
}

bool LightSet::light_is_at_infinity(std::uint32_t light) const {
    if (light < lights_.size()) return false;
    const std::size_t k = light - lights_.size();
    return k >= scene_lights_.size() || scene_lights_[k].light->type == SceneLight::Type::Directional;
}

bool LightSet::light_is_found_at_infinity(std::uint32_t light) const {
    if (light < lights_.size()) return false;
    const std::size_t k = light - lights_.size();
    return k >= scene_lights_.size() || scene_lights_[k].sun >= 0;
}

glm::vec3 LightSet::radiance_at_infinity(std::uint32_t light, const glm::vec3& dir) const {
    const std::size_t k = light - lights_.size();
    if (k >= scene_lights_.size()) return background_->radiance(dir);
    if (scene_lights_[k].sun < 0) return glm::vec3(0.0f);
    const Sun& sun = suns_[static_cast<std::size_t>(scene_lights_[k].sun)];
    return glm::dot(dir, sun.to_light) >= sun.cos_max ? sun.radiance : glm::vec3(0.0f);
}

float LightSet::nee_density_of_light(std::uint32_t light, const glm::vec3& p, const glm::vec3& to_light) const {
    const std::size_t k = light - lights_.size();
    if (k >= scene_lights_.size()) return background_probability_ * background_->pdf(p, to_light);
    const NonSurfaceLight& l = scene_lights_[k];
    if (l.sun < 0) return l.probability;  // delta: the selection alone, like sample()'s pdf
    const Sun& sun = suns_[static_cast<std::size_t>(l.sun)];
    return glm::dot(to_light, sun.to_light) >= sun.cos_max ? l.probability * uniform_cone_pdf(sun.omc) : 0.0f;
}

LightSet::EmissionDensity LightSet::emission_density(std::uint32_t light, const glm::vec3& normal,
                                                     const glm::vec3& dir) const {
    EmissionDensity d;
    if (light < lights_.size()) {
        const Light& l = lights_[light];
        d.pos = l.probability * surface_area_density(l.shape, normal);
        const float c = glm::dot(normal, dir);
        if (c > 0.0f) d.dir = c * kInvPi;
        else if (l.material->two_sided_emission && c < 0.0f) d.dir = -c * kInvPi;
        if (l.material->two_sided_emission) d.dir *= 0.5f;
        return d;
    }
    const std::size_t k = light - lights_.size();
    if (light_is_at_infinity(light)) {
        // Emission's direction density: for a background with a portal, not next event
        // estimation's (which depends on the shading point), so it is asked for on its own.
        d.pos = k >= scene_lights_.size() ? background_probability_ * background_->emission_pdf(-dir)
                                              : nee_density_of_light(light, glm::vec3(0.0f), -dir);
        d.dir = 1.0f / (kPi * bounds_radius_ * bounds_radius_);
        return d;
    }
    const SceneLight& sl = *scene_lights_[k].light;
    d.pos = scene_lights_[k].probability;
    if (sl.type == SceneLight::Type::Point) {
        d.dir = 1.0f / (4.0f * kPi);
    } else {
        d.dir = glm::dot(dir, sl.direction) >= sl.cos_cone ? uniform_cone_pdf(1.0f - sl.cos_cone) : 0.0f;
    }
    return d;
}

bool LightSet::sample_emission(float u_select, float u_part, float u1, float u2, float u3, float u4,
                               LightEmission& out) const {
    if (cdf_.empty()) return false;
    out = LightEmission{};
    out.light = light_of_sample(u_select);
    if (out.light >= lights_.size()) {
        const std::size_t k = out.light - lights_.size();
        if (k < scene_lights_.size()) return emit_scene_light(scene_lights_[k], u1, u2, u3, u4, out);
        // The background: a direction toward it as its emission draws it, travelling back.
        glm::vec3 to_light(0.0f);
        float pdf = 0.0f;
        if (!background_->sample_emission(u3, u4, to_light, pdf, out.le)) return false;
        out.selection = background_probability_;
        out.at_infinity = true;
        out.dir = -to_light;
        out.normal = out.dir;
        out.pdf_dir = pdf;
        const glm::vec2 d = bounds_radius_ * concentric_disk(u1, u2);
        const Frame f(to_light);
        out.point = bounds_centre_ + bounds_radius_ * to_light + d.x * f.s + d.y * f.t;
        out.pdf_pos = 1.0f / (kPi * bounds_radius_ * bounds_radius_);
        return out.pdf_dir > 0.0f && std::isfinite(out.pdf_dir) && luminance(out.le) > 0.0f;
    }
    const Light& l = lights_[out.light];
    SurfacePoint sp;
    out.pdf_pos = sample_area(l, u_part, u1, u2, sp);
    if (l.shape.strategy == ShapeLight::Strategy::ObjectArea) out.pdf_pos = object_area_density(l.shape, sp.normal);
    out.selection = l.probability;
    out.point = sp.point;
    out.point_error = sp.error;
    out.normal = glm::normalize(sp.normal);
    out.object = l.object;
    out.primitive = sp.primitive;
    // Two-sided: the back with probability 1/2, u3 stretched back onto [0, 1).
    glm::vec3 side = out.normal;
    float half = 1.0f;
    if (l.material->two_sided_emission) {
        half = 0.5f;
        if (u3 < 0.5f) {
            u3 = std::min(2.0f * u3, kBelowOne);
        } else {
            u3 = std::min(2.0f * u3 - 1.0f, kBelowOne);
            side = -side;
        }
    }
    const glm::vec3 local = cosine_hemisphere(u3, u4);
    out.dir = glm::normalize(Frame(side).to_world(local));
    out.pdf_dir = half * local.z * kInvPi;
    LightSample at;
    at.point = out.point;
    at.normal = out.normal;
    at.wi = -out.dir;
    out.le = emitted_radiance_at(l, at, sp.primitive);
    return out.pdf_pos > 0.0f && std::isfinite(out.pdf_pos) && out.pdf_dir > 0.0f && luminance(out.le) > 0.0f;
}

}  // namespace sweeptrace

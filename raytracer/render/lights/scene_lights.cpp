// LightSet's strategies for the scene's "lights" (point, spot, directional): see lights.hpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "collision/finite.hpp"
#include "raytracer/geometry/object_world_bounds.hpp"
#include "raytracer/render/guiding/sky_guide.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

namespace {

// The sphere around the world bounds of every object (meshes by their vertices' box), of radius
// at least 1 so that a scene of points still gives a directional light a weight.
float scene_radius(const Scene& scene, glm::vec3& centre) {
    const collision::Bounds3 world = scene_world_bounds(scene);
    centre = glm::vec3(0.0f);
    if (world.empty()) return 1.0f;
    centre = 0.5f * (world.lo + world.hi);
    if (!collision::finite(centre)) centre = glm::vec3(0.0f);
    const float r = 0.5f * glm::length(world.hi - world.lo);
    return std::isfinite(r) && r > 1.0f ? r : 1.0f;
}

// pbrt-v4's smooth spotlight edge: 1 inside the falloff start, 0 outside the cone, smoothstep
// in cos(theta) between.
float spot_falloff(const SceneLight& l, float cos_theta) {
    if (cos_theta >= l.cos_falloff_start) return 1.0f;
    if (cos_theta <= l.cos_cone) return 0.0f;
    const float t = (cos_theta - l.cos_cone) / (l.cos_falloff_start - l.cos_cone);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

void LightSet::add_scene_lights(const Scene& scene, std::vector<float>& weights) {
    float radius = -1.0f;  // the scene's bounding sphere, measured once when a light at infinity needs it
    for (const SceneLight& sl : scene.lights) {
        NonSurfaceLight l;
        l.light = &sl;
        float weight = 0.0f;
        switch (sl.type) {
        case SceneLight::Type::Point: weight = 4.0f * luminance(sl.intensity); break;
        case SceneLight::Type::Spot:
            weight = 2.0f * luminance(sl.intensity) * (1.0f - 0.5f * (sl.cos_falloff_start + sl.cos_cone));
            break;
        case SceneLight::Type::Directional: {
            // Bounds for emission sampling (light tracing from lights at infinity), not for the weight.
            if (radius < 0.0f) radius = bounds_radius_ = scene_radius(scene, bounds_centre_);
            weight = luminance(sl.irradiance);  // E: lights at infinity split their fixed share by it
            if (sl.half_angle > 0.0f) {
                Sun sun;
                sun.to_light = -sl.direction;
                const float s = std::sin(sl.half_angle);
                sun.cos_max = std::cos(sl.half_angle);
                sun.omc = s * s / (1.0f + sun.cos_max);  // 1 - cos, without cancellation
                sun.radiance = sl.irradiance / (kPi * s * s);
                l.sun = static_cast<int>(suns_.size());
                suns_.push_back(sun);
            }
            break;
        }
        }
        if (!(weight > 0.0f) || !std::isfinite(weight)) {
            if (l.sun >= 0) suns_.pop_back();
            continue;
        }
        scene_lights_.push_back(l);
        weights.push_back(weight);
    }
    // A colour or the sky without a portal stays with BSDF sampling alone: drawn uniformly over
    // the sphere, next event estimation finds a window no more often than cosine-weighted BSDF
    // sampling does, and its shadow rays cost more than its samples gain (1.19x the RMSE at equal
    // CPU time in scenes/sky-window.json without its portal; 1.25x the mean pixel variance at
    // equal spp on scenes/default.json, where it also takes half of the bulb's samples:
    // docs/sky-and-portals.md). pbrt-v4 comes to the same: its UniformInfiniteLight draws nothing
    // when MIS compensation is allowed. With a portal it is a light. Without one it is kept as
    // sky_, a light only where path guiding learned where it is seen (sky_guide.hpp).
    const Background& bg = scene.background;
    const bool sampled = bg.kind == Background::Kind::Environment || bg.has_portal;
    auto background = std::make_shared<const BackgroundLight>(bg);
    const float weight = static_cast<float>(background->max_irradiance());  // its E, as above
    if (sampled && background->emits() && weight > 0.0f && std::isfinite(weight)) {
        if (radius < 0.0f) radius = bounds_radius_ = scene_radius(scene, bounds_centre_);
        background_ = std::move(background);
        weights.push_back(weight);
    } else if (!sampled && background->emits() && weight > 0.0f && std::isfinite(weight)) {
        sky_ = std::move(background);
        sky_weight_ = weight;
    }
}

bool LightSet::sample_guided_sky(const SkyGuide& sky_guide, const glm::vec3& p, float u1, float u2, LightSample& out) const {
    float density = 0.0f;
    if (!sample_sky_mixture(sky_guide, p, glm::vec2(u1, u2), out.wi, density)) return false;
    out.pdf = sky_probability_ * density;
    out.radiance = sky_->radiance(out.wi);
    out.guided_sky = true;
    out.light = -1;
    out.at_infinity = true;
    out.distance = std::numeric_limits<float>::infinity();
    out.normal = -out.wi;
    out.point = glm::vec3(0.0f);  // unused: the shadow ray is unbounded
    return out.pdf > 0.0f && std::isfinite(out.pdf) && luminance(out.radiance) > 0.0f;
}

float LightSet::guided_sky_weight(const glm::vec3& from, const glm::vec3& dir, float bsdf_pdf,
                                  const SkyGuide* sky_guide) const {
    if (sky_guide == nullptr || !sky_ || !(bsdf_pdf > 0.0f)) return 1.0f;
    return power_heuristic(bsdf_pdf, sky_probability_ * sky_mixture_density(*sky_guide, from, dir));
}

bool LightSet::sample_background(const glm::vec3& p, float u1, float u2, LightSample& out) const {
    float pdf = 0.0f;
    if (!background_->sample(p, u1, u2, out.wi, pdf, out.radiance)) return false;
    out.pdf = background_probability_ * pdf;
    out.at_infinity = true;
    out.distance = std::numeric_limits<float>::infinity();
    out.normal = -out.wi;
    out.point = p + out.wi;  // unused: the shadow ray is unbounded
    return out.pdf > 0.0f && std::isfinite(out.pdf) && luminance(out.radiance) > 0.0f;
}

bool LightSet::sample_scene_light(const NonSurfaceLight& l, const glm::vec3& p, float u1, float u2,
                                  LightSample& out) const {
    const SceneLight& sl = *l.light;
    out.delta = true;
    out.pdf = l.probability;
    if (sl.type == SceneLight::Type::Directional) {
        out.at_infinity = true;
        out.distance = std::numeric_limits<float>::infinity();
        if (l.sun < 0) {
            out.wi = -sl.direction;
            out.radiance = sl.irradiance;
        } else {
            const Sun& sun = suns_[static_cast<std::size_t>(l.sun)];
            out.delta = false;
            out.wi = glm::normalize(Frame(sun.to_light).to_world(uniform_cone(u1, u2, sun.omc)));
            out.pdf = l.probability * uniform_cone_pdf(sun.omc);
            out.radiance = sun.radiance;
        }
        out.normal = -out.wi;
        out.point = p + out.wi;  // unused: the shadow ray is unbounded
        return out.pdf > 0.0f && std::isfinite(out.pdf);
    }
    const glm::vec3 w = sl.position - p;
    const float d2 = glm::dot(w, w);
    out.distance = std::sqrt(d2);
    if (!(out.distance > 0.0f) || !std::isfinite(d2)) return false;
    out.wi = w / out.distance;
    out.point = sl.position;
    out.point_error = glm::vec3(0.0f);  // the position is exact as given
    out.normal = -out.wi;
    const float falloff = sl.type == SceneLight::Type::Spot ? spot_falloff(sl, glm::dot(-out.wi, sl.direction)) : 1.0f;
    out.radiance = sl.intensity * (falloff / d2);
    return luminance(out.radiance) > 0.0f && std::isfinite(luminance(out.radiance));
}

glm::vec3 LightSet::escaped_radiance(const glm::vec3& from, const glm::vec3& dir, float bsdf_pdf,
                                     const SkyGuide* sky_guide) const {
    // Where the guided sky is a light, the others are chosen with what it leaves them.
    const float others = sky_guide != nullptr && sky_ ? 1.0f - sky_probability_ : 1.0f;
    glm::vec3 sum(0.0f);
    for (const Sun& sun : suns_) {
        if (!(glm::dot(dir, sun.to_light) >= sun.cos_max)) continue;
        const float w =
            bsdf_pdf > 0.0f ? power_heuristic(bsdf_pdf, others * sun.probability * uniform_cone_pdf(sun.omc)) : 1.0f;
        sum += sun.radiance * w;
    }
    if (background_) {
        const glm::vec3 le = background_->radiance(dir);
        const float w = bsdf_pdf > 0.0f
                            ? power_heuristic(bsdf_pdf, others * background_probability_ * background_->pdf(from, dir))
                            : 1.0f;
        sum += le * w;
    }
    return sum;
}

// Emission of a scene light (LightSet::sample_emission): a point or spot emits from its position
// (uniform over the sphere, or uniform in the spot's cone, the falloff in `le`); a light at
// infinity along a direction drawn as NEE draws it, from a point uniform on the disc of the
// bounding sphere that faces it.
bool LightSet::emit_scene_light(const NonSurfaceLight& l, float u1, float u2, float u3, float u4,
                                LightEmission& out) const {
    const SceneLight& sl = *l.light;
    out.selection = l.probability;
    if (sl.type != SceneLight::Type::Directional) {
        out.delta_position = true;
        out.point = sl.position;
        out.pdf_pos = 1.0f;
        if (sl.type == SceneLight::Type::Point) {
            out.dir = uniform_sphere(u3, u4);
            out.pdf_dir = 1.0f / (4.0f * kPi);
            out.le = sl.intensity;
        } else {
            const float omc = 1.0f - sl.cos_cone;
            out.dir = glm::normalize(Frame(sl.direction).to_world(uniform_cone(u3, u4, omc)));
            out.pdf_dir = uniform_cone_pdf(omc);
            out.le = sl.intensity * spot_falloff(sl, glm::dot(out.dir, sl.direction));
        }
        return out.pdf_dir > 0.0f && std::isfinite(out.pdf_dir) && luminance(out.le) > 0.0f;
    }
    glm::vec3 to_light = -sl.direction;
    out.at_infinity = true;
    if (l.sun < 0) {
        out.delta_direction = true;
        out.pdf_dir = 1.0f;
        out.le = sl.irradiance;
    } else {
        const Sun& sun = suns_[static_cast<std::size_t>(l.sun)];
        to_light = glm::normalize(Frame(sun.to_light).to_world(uniform_cone(u3, u4, sun.omc)));
        out.pdf_dir = uniform_cone_pdf(sun.omc);
        out.le = sun.radiance;
    }
    out.dir = -to_light;
    out.normal = out.dir;
    const glm::vec2 d = bounds_radius_ * concentric_disk(u1, u2);
    const Frame f(to_light);
    out.point = bounds_centre_ + bounds_radius_ * to_light + d.x * f.s + d.y * f.t;
    out.pdf_pos = 1.0f / (kPi * bounds_radius_ * bounds_radius_);
    return out.pdf_dir > 0.0f && std::isfinite(out.pdf_dir) && luminance(out.le) > 0.0f;
}

glm::vec3 LightSet::emission_toward(std::uint32_t light, const glm::vec3& point, const glm::vec3& normal,
                                     std::uint32_t primitive, const glm::vec3& dir) const {
    if (light < lights_.size()) {
        LightSample at;
        at.point = point;
        at.normal = normal;
        at.wi = -dir;
        return emitted_radiance_at(lights_[light], at, primitive);
    }
    const std::size_t k = light - lights_.size();
    if (k >= scene_lights_.size()) return glm::vec3(0.0f);
    const SceneLight& sl = *scene_lights_[k].light;
    if (sl.type == SceneLight::Type::Point) return sl.intensity;
    if (sl.type == SceneLight::Type::Spot) return sl.intensity * spot_falloff(sl, glm::dot(dir, sl.direction));
    return glm::vec3(0.0f);
}

collision::Bounds3 scene_world_bounds(const Scene& scene) {
    collision::Bounds3 world;
    for (const Object& obj : scene.objects) {
        const collision::Bounds3 box = object_world_bounds(obj, scene.meshes);
        if (!box.empty()) world.extend(box);
    }
    return world;
}

}  // namespace sweeptrace

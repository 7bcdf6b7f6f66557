// LightSet's strategies for the scene's "lights" (point, spot, directional): see lights.hpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "raytracer/render/lights.hpp"
#include "raytracer/render/sampling.hpp"

namespace sweeptrace {

namespace {

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
    if (scene.background.kind == Background::Kind::Environment && scene.background.environment) {
        auto env = std::make_shared<const EnvironmentLight>(scene.background);
        const float weight = static_cast<float>(env->luminance_integral());  // its E, as above
        if (env->emits() && weight > 0.0f && std::isfinite(weight)) {
            env_ = std::move(env);
            weights.push_back(weight);
        }
    }
}

bool LightSet::sample_environment(const glm::vec3& p, float u1, float u2, LightSample& out) const {
    float pdf = 0.0f;
    if (!env_->sample(u1, u2, out.wi, pdf, out.radiance)) return false;
    out.pdf = env_probability_ * pdf;
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

glm::vec3 LightSet::escaped_radiance(const glm::vec3& dir, float bsdf_pdf) const {
    glm::vec3 sum(0.0f);
    for (const Sun& sun : suns_) {
        if (!(glm::dot(dir, sun.to_light) >= sun.cos_max)) continue;
        const float w = bsdf_pdf > 0.0f ? power_heuristic(bsdf_pdf, sun.probability * uniform_cone_pdf(sun.omc)) : 1.0f;
        sum += sun.radiance * w;
    }
    if (env_) {
        const glm::vec3 le = env_->radiance(dir);
        const float w = bsdf_pdf > 0.0f ? power_heuristic(bsdf_pdf, env_probability_ * env_->pdf(dir)) : 1.0f;
        sum += le * w;
    }
    return sum;
}

}  // namespace sweeptrace

#include "raytracer/render/lights/background_light.hpp"

#include <algorithm>
#include <cmath>

#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

glm::vec3 background_radiance(const Background& bg, const glm::vec3& dir) {
    if (bg.kind == Background::Kind::Constant) return bg.color;
    if (bg.kind == Background::Kind::Environment) return environment_radiance(bg, dir);
    const float t = std::clamp(dir.y, 0.0f, 1.0f);
    return (1.0f - t) * bg.horizon + t * bg.zenith;
}

namespace {
constexpr float kInvFourPi = 1.0f / (4.0f * kPi);
}  // namespace

BackgroundLight::BackgroundLight(const Background& bg) : bg_(&bg) {
    if (bg.has_portal) portal_.emplace(bg.portal);
    switch (bg.kind) {
    case Background::Kind::Environment:
        if (bg.environment) {
            env_.emplace(bg);
            if (env_->emits()) max_irradiance_ = env_->max_irradiance();
        }
        break;
    case Background::Kind::Constant: max_irradiance_ = kPi * double(luminance(bg.color)); break;
    case Background::Kind::Sky:
        max_irradiance_ = kPi * double(std::max(luminance(bg.horizon), luminance(bg.zenith)));
        break;
    }
    if (!std::isfinite(max_irradiance_)) max_irradiance_ = 0.0;
}

bool BackgroundLight::sample(const glm::vec3& p, float u1, float u2, glm::vec3& dir, float& pdf,
                             glm::vec3& radiance) const {
    if (!portal_) return sample_emission(u1, u2, dir, pdf, radiance);
    if (!env_) {
        if (!portal_->sample(p, u1, u2, dir, pdf)) return false;
        radiance = background_radiance(*bg_, dir);
        return true;
    }
    // The map's half and the portal's, u1 stretched back onto [0, 1).
    if (u1 < 0.5f) {
        float env_pdf = 0.0f;
        if (!env_->sample(std::min(2.0f * u1, kBelowOne), u2, dir, env_pdf, radiance)) return false;
        pdf = 0.5f * (env_pdf + portal_->pdf(p, dir));
    } else {
        float portal_pdf = 0.0f;
        if (!portal_->sample(p, std::min(2.0f * u1 - 1.0f, kBelowOne), u2, dir, portal_pdf)) return false;
        radiance = env_->radiance(dir);
        pdf = 0.5f * (env_->pdf(dir) + portal_pdf);
    }
    return pdf > 0.0f && std::isfinite(pdf);
}

float BackgroundLight::pdf(const glm::vec3& p, const glm::vec3& dir) const {
    if (!portal_) return emission_pdf(dir);
    if (!env_) return portal_->pdf(p, dir);
    return 0.5f * (env_->pdf(dir) + portal_->pdf(p, dir));
}

bool BackgroundLight::sample_emission(float u1, float u2, glm::vec3& dir, float& pdf, glm::vec3& radiance) const {
    if (env_) return env_->sample(u1, u2, dir, pdf, radiance);
    dir = uniform_sphere(u1, u2);
    pdf = kInvFourPi;
    radiance = background_radiance(*bg_, dir);
    return true;
}

float BackgroundLight::emission_pdf(const glm::vec3& dir) const { return env_ ? env_->pdf(dir) : kInvFourPi; }

}  // namespace sweeptrace

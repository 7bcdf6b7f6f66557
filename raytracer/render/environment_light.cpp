#include "raytracer/render/environment_light.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/render/sampling.hpp"

namespace sweeptrace {

namespace {

constexpr double kPiD = 3.14159265358979323846;

// d' = R_y(-rotate) d and back: the right-handed rotation about +Y, x' = c x + s z, z' = -s x + c z.
glm::vec3 rotate_y(const glm::vec3& d, float degrees) {
    if (degrees == 0.0f) return d;
    const float a = degrees * kPi / 180.0f, c = std::cos(a), s = std::sin(a);
    return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

// (u, v) in [0, 1]^2 of a map-frame direction.
void direction_to_uv(const glm::vec3& d, float& u, float& v) {
    const float phi = std::atan2(d.x, -d.z);
    u = 0.5f + phi / (2.0f * kPi);
    v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
}

int texel(float t, int n) { return std::clamp(static_cast<int>(t * static_cast<float>(n)), 0, n - 1); }

}  // namespace

glm::vec3 environment_radiance(const Background& bg, const glm::vec3& dir) {
    const Image& img = *bg.environment;
    float u = 0.0f, v = 0.0f;
    direction_to_uv(rotate_y(dir, -bg.rotate_degrees), u, v);
    return bg.scale * img.at(texel(u, img.width), texel(v, img.height));
}

void EnvironmentLight::Distribution1D::build(std::vector<float> weights) {
    f = std::move(weights);
    cdf.assign(f.size() + 1, 0.0f);
    double running = 0.0;
    for (float w : f) running += w;
    sum = running;
    running = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        running += f[i];
        cdf[i + 1] = sum > 0.0 ? static_cast<float>(running / sum) : static_cast<float>(i + 1) / f.size();
    }
    cdf.back() = 1.0f;
}

float EnvironmentLight::Distribution1D::sample(float u, int& bin) const {
    // The first cdf entry above u closes the bin: cdf[bin] <= u < cdf[bin + 1], so a bin of
    // weight 0 (zero width) is never chosen.
    const auto it = std::upper_bound(cdf.begin() + 1, cdf.end(), u);
    bin = static_cast<int>(std::min<std::ptrdiff_t>(it - cdf.begin() - 1, static_cast<std::ptrdiff_t>(f.size()) - 1));
    const float lo = cdf[static_cast<std::size_t>(bin)], hi = cdf[static_cast<std::size_t>(bin) + 1];
    const float offset = hi > lo ? std::clamp((u - lo) / (hi - lo), 0.0f, 1.0f) : 0.5f;
    const float x = (static_cast<float>(bin) + offset) / static_cast<float>(f.size());
    return std::min(x, kBelowOne);
}

EnvironmentLight::EnvironmentLight(const Background& bg) : bg_(&bg) {
    const Image& img = *bg.environment;
    width_ = img.width;
    height_ = img.height;
    std::vector<float> row_sums(static_cast<std::size_t>(height_));
    rows_.resize(static_cast<std::size_t>(height_));
    const double cell = (2.0 * kPiD / width_) * (kPiD / height_);  // du dv -> d(phi) d(theta)
    for (int j = 0; j < height_; ++j) {
        const double sin_theta = std::sin((j + 0.5) * kPiD / height_);
        std::vector<float> w(static_cast<std::size_t>(width_));
        for (int i = 0; i < width_; ++i) {
            const float lum = luminance(bg.scale * img.at(i, j));
            w[static_cast<std::size_t>(i)] = static_cast<float>(lum * sin_theta);
            integral_ += lum * sin_theta * cell;  // midpoint rule in theta: a stand-in, used only for selection
        }
        rows_[static_cast<std::size_t>(j)].build(std::move(w));
        row_sums[static_cast<std::size_t>(j)] = static_cast<float>(rows_[static_cast<std::size_t>(j)].sum);
        total_ += rows_[static_cast<std::size_t>(j)].sum;
    }
    marginal_.build(std::move(row_sums));
}

bool EnvironmentLight::sample(float u1, float u2, glm::vec3& dir, float& pdf, glm::vec3& radiance) const {
    int row = 0, col = 0;
    const float v = marginal_.sample(u2, row);
    const float u = rows_[static_cast<std::size_t>(row)].sample(u1, col);
    const float theta = v * kPi, phi = (u - 0.5f) * 2.0f * kPi;
    const float sin_theta = std::sin(theta);
    if (!(sin_theta > 0.0f)) return false;
    const glm::vec3 local(sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi));
    dir = rotate_y(local, bg_->rotate_degrees);
    const float p_uv = marginal_.density(row) * rows_[static_cast<std::size_t>(row)].density(col);
    pdf = p_uv / (2.0f * kPi * kPi * sin_theta);
    radiance = environment_radiance(*bg_, dir);  // what a ray escaping along dir sees
    return pdf > 0.0f && std::isfinite(pdf);
}

float EnvironmentLight::pdf(const glm::vec3& dir) const {
    float u = 0.0f, v = 0.0f;
    const glm::vec3 local = rotate_y(dir, -bg_->rotate_degrees);
    direction_to_uv(local, u, v);
    const int row = texel(v, height_), col = texel(u, width_);
    // From x and z, not sqrt(1 - y^2), which cancels near the poles (1 % off at theta ~ 0.01).
    const float sin_theta = std::sqrt(local.x * local.x + local.z * local.z) / glm::length(local);
    if (!(sin_theta > 0.0f) || marginal_.f[static_cast<std::size_t>(row)] <= 0.0f) return 0.0f;
    const float p_uv = marginal_.density(row) * rows_[static_cast<std::size_t>(row)].density(col);
    return p_uv / (2.0f * kPi * kPi * sin_theta);
}

}  // namespace sweeptrace

#include "raytracer/render/materials/coat_albedo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/materials/microfacet.hpp"

namespace sweeptrace {

namespace {

constexpr int kMu = 64, kRough = 64, kStrata = 32;

struct Table {
    std::array<float, kMu * kRough> albedo{};
    std::array<float, kRough> mean{};
};

// mu = t^2 on a uniform t grid: the albedo changes fastest toward grazing, where the grid is
// densest (spacing 2.5e-4 in mu at the first step).
float grid_mu(int i) {
    const float t = static_cast<float>(i) / (kMu - 1);
    return std::max(t * t, 1e-4f);
}
float grid_roughness(int j) { return static_cast<float>(j) / (kRough - 1); }

std::unique_ptr<Table> build(float eta) {
    auto t = std::make_unique<Table>();
    for (int j = 0; j < kRough; ++j) {
        const float alpha = coat_alpha(grid_roughness(j));
        double mean = 0.0;  // trapezoid rule in mu
        for (int i = 0; i < kMu; ++i) {
            const float e = std::min(1.0f, coat_lobe_albedo(eta, alpha, grid_mu(i), kStrata) + kCoatAlbedoMargin);
            t->albedo[static_cast<std::size_t>(j * kMu + i)] = e;
            // 2 int E mu dmu = int E 4 t^3 dt on the t grid (trapezoid rule).
            const double tg = static_cast<double>(i) / (kMu - 1), w = (i == 0 || i == kMu - 1) ? 0.5 : 1.0;
            mean += w * 4.0 * e * tg * tg * tg / (kMu - 1);
        }
        t->mean[static_cast<std::size_t>(j)] = static_cast<float>(mean);
    }
    return t;
}

const Table& table_for(float eta) {
    thread_local float last_eta = -1.0f;
    thread_local const Table* last = nullptr;
    if (eta == last_eta) return *last;
    static std::mutex mutex;
    static std::map<float, std::unique_ptr<Table>> tables;
    const std::lock_guard<std::mutex> lock(mutex);
    auto& slot = tables[eta];
    if (!slot) slot = build(eta);
    last_eta = eta;
    last = slot.get();
    return *last;
}

}  // namespace

// E(mu) by visible-normal sampling on a stratified grid: each sample's weight is F G2 / G1 (the
// metal's estimator with the dielectric's Fresnel), directions below the surface count 0.
float coat_lobe_albedo(float eta, float alpha, float mu, int strata) {
    const glm::vec3 wo(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
    const float lo = ggx_lambda(wo, alpha);
    double sum = 0.0;
    for (int a = 0; a < strata; ++a)
        for (int b = 0; b < strata; ++b) {
            const glm::vec3 h = sample_ggx_vndf(wo, alpha, (a + 0.5f) / strata, (b + 0.5f) / strata);
            const float wo_h = glm::dot(wo, h);
            const glm::vec3 wi = 2.0f * wo_h * h - wo;
            if (wi.z <= 0.0f || wo_h <= 0.0f) continue;
            float cos_t = 0.0f;
            const float f = fresnel_dielectric(std::min(wo_h, 1.0f), eta, cos_t);
            sum += f * (1.0f + lo) / (1.0f + lo + ggx_lambda(wi, alpha));
        }
    return static_cast<float>(sum / (strata * strata));
}

float coat_alpha(float roughness) { return std::max(roughness * roughness, kMinMetalAlpha); }

CoatAlbedo coat_albedo(float eta, float roughness, float mu) {
    const Table& t = table_for(eta);
    const float x = std::sqrt(std::clamp(mu, 0.0f, 1.0f)) * (kMu - 1), y = std::clamp(roughness, 0.0f, 1.0f) * (kRough - 1);
    const int i = std::min(static_cast<int>(x), kMu - 2), j = std::min(static_cast<int>(y), kRough - 2);
    const float fx = x - i, fy = y - j;
    const auto at = [&](int jj, int ii) { return t.albedo[static_cast<std::size_t>(jj * kMu + ii)]; };
    const float e0 = at(j, i) + fx * (at(j, i + 1) - at(j, i));
    const float e1 = at(j + 1, i) + fx * (at(j + 1, i + 1) - at(j + 1, i));
    CoatAlbedo c;
    c.albedo = e0 + fy * (e1 - e0);
    c.mean_albedo = t.mean[static_cast<std::size_t>(j)] + fy * (t.mean[static_cast<std::size_t>(j + 1)] - t.mean[static_cast<std::size_t>(j)]);
    return c;
}

}  // namespace sweeptrace

#include "raytracer/render/lights/environment_light.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "raytracer/render/sampling/equal_area_octahedral.hpp"
#include "raytracer/render/sampling/sampling.hpp"

namespace sweeptrace {

namespace {

constexpr double kPiD = 3.14159265358979323846;

// d' = R_y(-rotate) d and back: the right-handed rotation about +Y, x' = c x + s z, z' = -s x + c z.
glm::vec3 rotate_y(const glm::vec3& d, float degrees) {
    if (degrees == 0.0f) return d;
    const float a = degrees * kPi / 180.0f, c = std::cos(a), s = std::sin(a);
    return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

// The map frame: d' = S R^-1 d, R the turn (about +Y by rotate_degrees, or any rotation), S =
// diag(-1, 1, 1) when mirrored; and back, d = R S d'.
glm::vec3 to_map_frame(const Background& bg, const glm::vec3& d) {
    // d * turn is turn^T d, the inverse rotation, without forming the transpose per lookup.
    glm::vec3 m = bg.turned ? d * bg.turn : rotate_y(d, -bg.rotate_degrees);
    if (bg.mirror) m.x = -m.x;
    return m;
}

glm::vec3 from_map_frame(const Background& bg, glm::vec3 m) {
    if (bg.mirror) m.x = -m.x;
    return bg.turned ? bg.turn * m : rotate_y(m, bg.rotate_degrees);
}

// (u, v) in [0, 1]^2 of a map-frame direction, equirectangular.
void direction_to_uv(const glm::vec3& d, float& u, float& v) {
    const float phi = std::atan2(d.x, -d.z);
    u = 0.5f + phi / (2.0f * kPi);
    v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
}

bool is_equal_area(const Background& bg) { return bg.mapping == Background::EnvironmentMapping::EqualArea; }

// (u, v) of a map-frame direction in the background's layout; equal-area through pbrt's z-up
// light space w = (d'.x, -d'.z, d'.y).
void map_uv(const Background& bg, const glm::vec3& m, float& u, float& v) {
    if (!is_equal_area(bg)) return direction_to_uv(m, u, v);
    const glm::vec2 p = equal_area_sphere_to_square({m.x, -m.z, m.y});
    u = p.x;
    v = p.y;
}

// The map-frame direction of an equal-area (u, v): d' = (w.x, w.z, -w.y).
glm::vec3 equal_area_direction(float u, float v) {
    const glm::vec3 w = equal_area_square_to_sphere({u, v});
    return {w.x, w.z, -w.y};
}

// The 9 real spherical harmonics of order <= 2 at unit direction d, each times the clamped cosine's
// convolution factor A_l (pi, 2 pi / 3, pi / 4): sum_k c_k sh_k(n) is then the irradiance at
// normal n of a map whose coefficients are c_k = int L sh_k d omega (Ramamoorthi and Hanrahan 2001).
std::array<double, 9> sh_order2(const glm::vec3& d, bool convolved) {
    const double x = d.x, y = d.y, z = d.z;
    const double a0 = convolved ? kPiD : 1.0, a1 = convolved ? 2.0 * kPiD / 3.0 : 1.0, a2 = convolved ? kPiD / 4.0 : 1.0;
    return {a0 * 0.282095,           a1 * 0.488603 * y,      a1 * 0.488603 * z,
            a1 * 0.488603 * x,       a2 * 1.092548 * x * y,  a2 * 1.092548 * y * z,
            a2 * 0.315392 * (3.0 * z * z - 1.0), a2 * 1.092548 * x * z, a2 * 0.546274 * (x * x - y * y)};
}

// The largest irradiance over 256 orientations spread evenly on the sphere (a Fibonacci spiral),
// from the map's coefficients; at least the mean over all orientations, int L d omega / 4 (the
// order-1 and order-2 terms average to zero), so positive for any map that emits.
double max_irradiance_of(const std::array<double, 9>& coefficients, double integral) {
    constexpr int kOrientations = 256;
    double best = integral / 4.0;
    for (int k = 0; k < kOrientations; ++k) {
        const double z = 1.0 - (2.0 * k + 1.0) / kOrientations;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = k * kPiD * (3.0 - std::sqrt(5.0));  // the golden angle
        const std::array<double, 9> y = sh_order2(glm::vec3(r * std::cos(phi), r * std::sin(phi), z), true);
        double e = 0.0;
        for (std::size_t i = 0; i < 9; ++i) e += coefficients[i] * y[i];
        best = std::max(best, e);
    }
    return best;
}

int texel(float t, int n) { return std::clamp(static_cast<int>(t * static_cast<float>(n)), 0, n - 1); }

}  // namespace

EnvironmentLookup look_up_environment(const Background& bg, const glm::vec3& dir) {
    const Image& img = *bg.environment;
    EnvironmentLookup l;
    l.local = to_map_frame(bg, dir);
    float u = 0.0f, v = 0.0f;
    map_uv(bg, l.local, u, v);
    l.col = texel(u, img.width);
    l.row = texel(v, img.height);
    return l;
}

glm::vec3 environment_radiance(const Background& bg, const glm::vec3& dir) {
    const EnvironmentLookup l = look_up_environment(bg, dir);
    return bg.scale * bg.environment->at(l.col, l.row);
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
    // Equal-area: every texel subtends the same solid angle, so the weight is the luminance
    // alone (the Jacobian is the constant 4 pi) and the integral below is exact.
    const bool equal_area = is_equal_area(bg);
    const double cell = equal_area ? 4.0 * kPiD / (static_cast<double>(width_) * height_)
                                   : (2.0 * kPiD / width_) * (kPiD / height_);  // du dv -> d(phi) d(theta)
    std::array<double, 9> coefficients{};  // int lum(L) sh_k d omega, in the map's frame
    std::vector<float> sin_phi(static_cast<std::size_t>(width_)), cos_phi(sin_phi.size());  // equirect columns
    for (int i = 0; i < width_; ++i) {
        const float phi = ((i + 0.5f) / static_cast<float>(width_) - 0.5f) * 2.0f * kPi;
        sin_phi[static_cast<std::size_t>(i)] = std::sin(phi);
        cos_phi[static_cast<std::size_t>(i)] = std::cos(phi);
    }
    for (int j = 0; j < height_; ++j) {
        // The row's Jacobian factor J_j: sin(theta_j) at the row's centre (equirect), 1 (equal-area).
        const double jacobian = equal_area ? 1.0 : std::sin((j + 0.5) * kPiD / height_);
        const float v = (j + 0.5f) / static_cast<float>(height_);
        const float sin_theta = std::sin(v * kPi), cos_theta = std::cos(v * kPi);  // equirect: the row's centre
        std::vector<float> w(static_cast<std::size_t>(width_));
        for (int i = 0; i < width_; ++i) {
            const float lum = luminance(bg.scale * img.at(i, j));
            w[static_cast<std::size_t>(i)] = static_cast<float>(lum * jacobian);
            // Equirect: the midpoint rule in theta, a stand-in used only for selection; equal-area: exact.
            integral_ += lum * jacobian * cell;
            if (lum > 0.0f) {
                // The texel's centre in the map's frame (the maximum over orientations does not
                // depend on the frame).
                const auto c = static_cast<std::size_t>(i);
                const glm::vec3 d = equal_area ? equal_area_direction((i + 0.5f) / static_cast<float>(width_), v)
                                               : glm::vec3(sin_theta * sin_phi[c], cos_theta, -sin_theta * cos_phi[c]);
                const std::array<double, 9> y = sh_order2(d, false);
                for (std::size_t k = 0; k < 9; ++k) coefficients[k] += lum * jacobian * cell * y[k];
            }
        }
        rows_[static_cast<std::size_t>(j)].build(std::move(w));
        row_sums[static_cast<std::size_t>(j)] = static_cast<float>(rows_[static_cast<std::size_t>(j)].sum);
        total_ += rows_[static_cast<std::size_t>(j)].sum;
    }
    marginal_.build(std::move(row_sums));
    max_irradiance_ = max_irradiance_of(coefficients, integral_);
}

bool EnvironmentLight::sample(float u1, float u2, glm::vec3& dir, float& pdf, glm::vec3& radiance) const {
    int row = 0, col = 0;
    const float v = marginal_.sample(u2, row);
    const float u = rows_[static_cast<std::size_t>(row)].sample(u1, col);
    if (is_equal_area(*bg_)) {
        // The density and radiance of the texel dir maps back to (the sampled one but for rounding
        // on a texel's edge), so sample(), pdf() and a ray escaping along dir agree exactly.
        dir = from_map_frame(*bg_, equal_area_direction(u, v));
        const EnvironmentLookup l = look_up_environment(*bg_, dir);  // one lookup for both
        pdf = density(l);
        radiance = bg_->scale * bg_->environment->at(l.col, l.row);
        return pdf > 0.0f && std::isfinite(pdf);
    }
    const float theta = v * kPi, phi = (u - 0.5f) * 2.0f * kPi;
    const float sin_theta = std::sin(theta);
    if (!(sin_theta > 0.0f)) return false;
    const glm::vec3 local(sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi));
    dir = from_map_frame(*bg_, local);
    const float p_uv = marginal_.density(row) * rows_[static_cast<std::size_t>(row)].density(col);
    pdf = p_uv / (2.0f * kPi * kPi * sin_theta);
    radiance = environment_radiance(*bg_, dir);  // what a ray escaping along dir sees
    return pdf > 0.0f && std::isfinite(pdf);
}

float EnvironmentLight::pdf(const glm::vec3& dir) const { return density(look_up_environment(*bg_, dir)); }

float EnvironmentLight::density(const EnvironmentLookup& l) const {
    if (marginal_.f[static_cast<std::size_t>(l.row)] <= 0.0f) return 0.0f;
    const float p_uv = marginal_.density(l.row) * rows_[static_cast<std::size_t>(l.row)].density(l.col);
    if (is_equal_area(*bg_)) return p_uv / (4.0f * kPi);
    // From x and z, not sqrt(1 - y^2), which cancels near the poles (1 % off at theta ~ 0.01).
    const glm::vec3& local = l.local;
    const float sin_theta = std::sqrt(local.x * local.x + local.z * local.z) / glm::length(local);
    if (!(sin_theta > 0.0f)) return 0.0f;
    return p_uv / (2.0f * kPi * kPi * sin_theta);
}

}  // namespace sweeptrace

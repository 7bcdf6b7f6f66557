#include "raytracer/image/diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "collision/finite.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

using collision::finite;

glm::dvec3 in_space(const glm::vec3& p, DiffSpace space) {
    if (space == DiffSpace::Linear) return glm::dvec3(p);
    return glm::dvec3(srgb_encode(p.x), srgb_encode(p.y), srgb_encode(p.z));
}

void require_same_size(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw InputError("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
                         std::to_string(b.width) + "x" + std::to_string(b.height));
}

// Separable Gaussian blur (sigma 1 px, radius 3 sigma, edges clamped) of linear RGB clamped to [0, 1].
std::vector<glm::dvec3> blurred(const Image& image) {
    constexpr int radius = 3;
    double weights[2 * radius + 1];
    double total = 0.0;
    for (int i = -radius; i <= radius; ++i) total += weights[i + radius] = std::exp(-0.5 * i * i);
    for (double& w : weights) w /= total;
    const int w = image.width, h = image.height;
    std::vector<glm::dvec3> src(image.pixels.size()), tmp(image.pixels.size()), out(image.pixels.size());
    for (std::size_t i = 0; i < src.size(); ++i)
        src[i] = finite(image.pixels[i]) ? glm::clamp(glm::dvec3(image.pixels[i]), 0.0, 1.0) : glm::dvec3(0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::dvec3 s(0.0);
            for (int i = -radius; i <= radius; ++i) s += weights[i + radius] * src[std::size_t(y) * w + std::clamp(x + i, 0, w - 1)];
            tmp[std::size_t(y) * w + x] = s;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::dvec3 s(0.0);
            for (int i = -radius; i <= radius; ++i) s += weights[i + radius] * tmp[std::size_t(std::clamp(y + i, 0, h - 1)) * w + x];
            out[std::size_t(y) * w + x] = s;
        }
    return out;
}

// Linear sRGB (D65) -> CIE XYZ -> CIELAB relative to the D65 white.
glm::dvec3 to_lab(const glm::dvec3& rgb) {
    const double X = 0.4124564 * rgb.r + 0.3575761 * rgb.g + 0.1804375 * rgb.b;
    const double Y = 0.2126729 * rgb.r + 0.7151522 * rgb.g + 0.0721750 * rgb.b;
    const double Z = 0.0193339 * rgb.r + 0.1191920 * rgb.g + 0.9503041 * rgb.b;
    auto f = [](double t) {
        constexpr double d = 6.0 / 29.0;
        return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
    };
    const double fx = f(X / 0.95047), fy = f(Y / 1.0), fz = f(Z / 1.08883);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

glm::vec3 false_colour(double t) {
    static const glm::vec3 stops[] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    constexpr int n = sizeof(stops) / sizeof(stops[0]);
    t = std::clamp(t, 0.0, 1.0) * (n - 1);
    const int i = std::min(static_cast<int>(t), n - 2);
    const float f = static_cast<float>(t - i);
    return stops[i] * (1.0f - f) + stops[i + 1] * f;
}

// Largest possible |golden - truth| in linear units for a pixel stored as the nearest 8-bit sRGB
// code: half a code step either way, mapped through the decode curve.
double quantisation_bound(float linear) {
    const double code = std::round(static_cast<double>(srgb_encode(linear)) * 255.0);
    const double up = srgb_decode(static_cast<float>(std::min(255.0, code + 0.5) / 255.0));
    const double down = srgb_decode(static_cast<float>(std::max(0.0, code - 0.5) / 255.0));
    const double here = srgb_decode(static_cast<float>(code / 255.0));
    return std::max(up - here, here - down);
}

}  // namespace

DiffMetrics compare_images(const Image& a, const Image& b, const DiffOptions& options) {
    require_same_size(a, b);
    DiffMetrics m;
    m.width = a.width;
    m.height = a.height;
    const std::size_t n = a.pixels.size();
    if (n == 0) return m;
    double sum_sq = 0.0, sum_abs = 0.0;
    std::size_t over = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const bool fa = finite(a.pixels[i]), fb = finite(b.pixels[i]);
        m.non_finite_a += !fa;
        m.non_finite_b += !fb;
        if (!fa || !fb) {  // counts as differing, but cannot enter the sums
            ++over;
            continue;
        }
        if (options.space == DiffSpace::Linear)
            m.psnr_peak = std::max({m.psnr_peak, double(a.pixels[i].x), double(a.pixels[i].y), double(a.pixels[i].z),
                                    double(b.pixels[i].x), double(b.pixels[i].y), double(b.pixels[i].z)});
        const glm::dvec3 d = glm::abs(in_space(a.pixels[i], options.space) - in_space(b.pixels[i], options.space));
        sum_sq += glm::dot(d, d);
        sum_abs += d.x + d.y + d.z;
        const double worst = std::max({d.x, d.y, d.z});
        if (worst > options.pixel_threshold) ++over;
        if (worst > m.max_abs) {
            m.max_abs = worst;
            m.max_x = static_cast<int>(i % a.width);
            m.max_y = static_cast<int>(i / a.width);
        }
    }
    const double samples = 3.0 * static_cast<double>(n);
    m.rmse = std::sqrt(sum_sq / samples);
    m.psnr = m.rmse > 0.0 ? 20.0 * std::log10(m.psnr_peak / m.rmse) : std::numeric_limits<double>::infinity();
    m.mean_abs = sum_abs / samples;
    m.share_over = static_cast<double>(over) / static_cast<double>(n);

    const std::vector<glm::dvec3> ba = blurred(a), bb = blurred(b);
    double sum_e = 0.0;
    std::size_t noticeable = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double e = glm::length(to_lab(ba[i]) - to_lab(bb[i]));
        sum_e += e;
        noticeable += e > 2.3;
    }
    m.mean_delta_e = sum_e / static_cast<double>(n);
    m.share_delta_e_over_jnd = static_cast<double>(noticeable) / static_cast<double>(n);
    return m;
}

Image difference_heatmap(const Image& a, const Image& b, const DiffOptions& options, double scale) {
    require_same_size(a, b);
    Image out(a.width, a.height);
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (!finite(a.pixels[i]) || !finite(b.pixels[i])) {
            out.pixels[i] = {1.0f, 0.0f, 1.0f};
            continue;
        }
        const glm::dvec3 d = glm::abs(in_space(a.pixels[i], options.space) - in_space(b.pixels[i], options.space));
        // The ramp is built in display terms; write_image encodes to sRGB, so decode here to get
        // exactly these colours in the PNG.
        const glm::vec3 c = false_colour(std::max({d.x, d.y, d.z}) / scale);
        out.pixels[i] = {srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b)};
    }
    return out;
}

MeanAndVariance combine_halves(const Image& a, const Image& b) {
    require_same_size(a, b);
    MeanAndVariance r{Image(a.width, a.height), Image(a.width, a.height)};
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        r.mean.pixels[i] = 0.5f * (a.pixels[i] + b.pixels[i]);
        const glm::vec3 d = a.pixels[i] - b.pixels[i];
        r.variance.pixels[i] = 0.25f * d * d;
    }
    return r;
}

double normal_two_sided_quantile(double p) {
    // P(|Z| > z) = erfc(z / sqrt 2), decreasing in z.
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

BlockTestResult block_test(const Image& reference, const Image& actual, const Image& actual_variance,
                           const BlockTestOptions& options) {
    require_same_size(reference, actual);
    require_same_size(reference, actual_variance);
    if (options.null_variance) require_same_size(reference, *options.null_variance);
    if (options.block <= 0) throw InputError("block size must be positive");
    if (options.mask && options.mask->size() != reference.pixels.size())
        throw InputError("block test mask has " + std::to_string(options.mask->size()) + " entries for " +
                         std::to_string(reference.pixels.size()) + " pixels");
    BlockTestResult r;
    const int B = options.block;
    r.blocks_x = (reference.width + B - 1) / B;
    r.blocks_y = (reference.height + B - 1) / B;
    r.block_z.assign(static_cast<std::size_t>(r.blocks_x) * r.blocks_y, -1.0);
    // Blocks first, so the Bonferroni count is the number of tests actually made.
    struct Sums {
        glm::dvec3 actual{0.0}, reference{0.0}, variance{0.0}, bound{0.0};
        int count = 0;
        bool broken = false;
    };
    std::vector<Sums> sums(r.block_z.size());
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * reference.width + x;
            if (options.mask && !(*options.mask)[i]) continue;
            Sums& s = sums[static_cast<std::size_t>(y / B) * r.blocks_x + x / B];
            const glm::vec3& a = actual.pixels[i];
            glm::vec3 g = reference.pixels[i];
            if (options.golden_is_8bit)  // saturated: one-sided, a render at or above 1 agrees
                for (int c = 0; c < 3; ++c)
                    if (g[c] >= 1.0f) g[c] = std::max(a[c], 1.0f);
            glm::vec3 v = actual_variance.pixels[i];
            if (options.null_variance) v = glm::max(v, options.null_variance->pixels[i]);
            if (!finite(a) || !finite(v) || !finite(g)) s.broken = true;
            s.actual += glm::dvec3(a);
            s.reference += glm::dvec3(g);
            s.variance += glm::dvec3(v);
            for (int c = 0; c < 3; ++c)
                s.bound[c] += options.relative_tolerance * std::abs(g[c]) +
                              (options.golden_is_8bit ? quantisation_bound(g[c]) : 0.0);
            ++s.count;
        }
    for (const Sums& s : sums) r.blocks_tested += s.count > 0;
    const double tests = 3.0 * static_cast<double>(std::max<std::size_t>(1, r.blocks_tested));
    r.z_limit = options.z_limit > 0.0 ? options.z_limit : normal_two_sided_quantile(options.false_alarm / tests);
    bool first = true;
    for (std::size_t b = 0; b < sums.size(); ++b) {
        const Sums& s = sums[b];
        if (s.count == 0) continue;
        double block_max = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = (s.actual[c] - s.reference[c]) / s.count;
            const double excess = std::max(0.0, std::abs(d) - s.bound[c] / s.count);
            const double sigma = std::sqrt(s.variance[c] * (1.0 + options.reference_noise_ratio)) / s.count;
            double z = 0.0;
            if (s.broken || !std::isfinite(d))
                z = std::numeric_limits<double>::infinity();
            else if (excess > 0.0)
                z = sigma > 0.0 ? excess / sigma : std::numeric_limits<double>::infinity();
            block_max = std::max(block_max, z);
            if (first || z > r.max_z) {
                first = false;
                r.max_z = z;
                r.worst_bx = static_cast<int>(b % r.blocks_x);
                r.worst_by = static_cast<int>(b / r.blocks_x);
                r.worst_channel = c;
                r.worst_difference = d;
                r.worst_sigma = sigma;
            }
        }
        r.block_z[b] = block_max;
        r.blocks_over += block_max > r.z_limit;
    }
    return r;
}

Image block_z_heatmap(const BlockTestResult& result, int width, int height, int block) {
    Image out(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t b = static_cast<std::size_t>(y / block) * result.blocks_x + x / block;
            const double z = b < result.block_z.size() ? result.block_z[b] : -1.0;
            const glm::vec3 c = z < 0.0 ? glm::vec3(0.2f) : false_colour(z / (2.0 * result.z_limit));
            out.at(x, y) = {srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b)};
        }
    return out;
}

std::string BlockTestResult::summary() const {
    char text[400];
    std::snprintf(text, sizeof text,
                  "block test: max z %.6g (limit %.6g, %s) at block (%d, %d) channel %c: mean difference %+.9g, "
                  "sigma %.9g; %zu of %zu blocks over",
                  max_z, z_limit, pass() ? "pass" : "FAIL", worst_bx, worst_by, "RGB"[worst_channel], worst_difference,
                  worst_sigma, blocks_over, blocks_tested);
    return text;
}

}  // namespace sweeptrace

// FLIP and HDR-FLIP; the formulas and constants are restated in docs/flip.md, section by section.
#include "raytracer/image/flip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "raytracer/image/flip_color.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

using Plane = std::vector<double>;
using Kernel = std::vector<double>;  // index i <-> offset i - radius

constexpr double pi = std::numbers::pi;

// Correlation with kx along rows then ky along columns; coordinates clamped to the image.
Plane filter_separable(const Plane& src, int w, int h, const Kernel& kx, const Kernel& ky) {
    const int rx = static_cast<int>(kx.size() / 2), ry = static_cast<int>(ky.size() / 2);
    Plane tmp(src.size()), out(src.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int i = -rx; i <= rx; ++i) s += kx[i + rx] * src[std::size_t(y) * w + std::clamp(x + i, 0, w - 1)];
            tmp[std::size_t(y) * w + x] = s;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int i = -ry; i <= ry; ++i) s += ky[i + ry] * tmp[std::size_t(std::clamp(y + i, 0, h - 1)) * w + x];
            out[std::size_t(y) * w + x] = s;
        }
    return out;
}

// One Gaussian of a contrast sensitivity function, a exp(-b f^2) in frequency (f in cycles per
// degree), whose spatial form is a sqrt(pi / b) exp(-pi^2 x^2 / b) (x in degrees).
struct CsfTerm {
    double a, b;
};
struct Csf {
    CsfTerm terms[2];
};
// Achromatic, red-green, blue-yellow (FLIP's table 1); a = 0 terms are absent.
constexpr Csf csf_of_channel[3] = {{{{1.0, 0.0047}, {0.0, 1e-5}}},
                                   {{{1.0, 0.0053}, {0.0, 1e-5}}},
                                   {{{34.1, 0.04}, {13.5, 0.025}}}};
constexpr double csf_largest_b = 0.04;

// One channel filtered by its CSF: the 2-D kernel sum_k A_k exp(-pi^2 (x^2 + y^2) / b_k) on the
// pixel grid, normalised to sum 1, applied as one separable pass per Gaussian term.
Plane csf_filter(const Plane& channel, int w, int h, const Csf& csf, double ppd) {
    const int radius = static_cast<int>(std::ceil(3.0 * std::sqrt(csf_largest_b / (2.0 * pi * pi)) * ppd));
    Kernel kernels[2];
    double amplitude[2] = {0.0, 0.0}, total = 0.0;
    for (int k = 0; k < 2; ++k) {
        const CsfTerm& t = csf.terms[k];
        if (t.a == 0.0) continue;
        double sum = 0.0;
        for (int i = -radius; i <= radius; ++i) {
            const double x = i / ppd;
            kernels[k].push_back(std::exp(-pi * pi * x * x / t.b));
            sum += kernels[k].back();
        }
        amplitude[k] = t.a * std::sqrt(pi / t.b);
        total += amplitude[k] * sum * sum;
    }
    Plane out(channel.size(), 0.0);
    for (int k = 0; k < 2; ++k) {
        if (amplitude[k] == 0.0) continue;
        const Plane part = filter_separable(channel, w, h, kernels[k], kernels[k]);
        const double weight = amplitude[k] / total;
        for (std::size_t i = 0; i < out.size(); ++i) out[i] += weight * part[i];
    }
    return out;
}

// Each image's colours as the eye resolves them at this distance: YCxCz, filtered per channel,
// back to linear RGB and clamped to [0, 1] (the filtered colour can leave the gamut).
std::vector<glm::dvec3> spatially_filtered(const std::vector<glm::dvec3>& rgb, int w, int h, double ppd) {
    Plane channels[3];
    for (auto& c : channels) c.resize(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const glm::dvec3 o = flip_color::xyz_to_ycxcz(flip_color::linear_rgb_to_xyz(rgb[i]));
        for (int c = 0; c < 3; ++c) channels[c][i] = o[c];
    }
    for (int c = 0; c < 3; ++c) channels[c] = csf_filter(channels[c], w, h, csf_of_channel[c], ppd);
    std::vector<glm::dvec3> out(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const glm::dvec3 o(channels[0][i], channels[1][i], channels[2][i]);
        out[i] = glm::clamp(flip_color::xyz_to_linear_rgb(flip_color::ycxcz_to_xyz(o)), 0.0, 1.0);
    }
    return out;
}

// Y / Yn of each pixel, the achromatic channel FLIP detects features in.
Plane achromatic(const std::vector<glm::dvec3>& rgb) {
    Plane y(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i)
        y[i] = (flip_color::xyz_to_ycxcz(flip_color::linear_rgb_to_xyz(rgb[i])).x + 16.0) / 116.0;
    return y;
}

std::vector<float> ldr_flip_map(const std::vector<glm::dvec3>& reference, const std::vector<glm::dvec3>& test,
                                int w, int h, double ppd) {
    const std::vector<glm::dvec3> fr = spatially_filtered(reference, w, h, ppd);
    const std::vector<glm::dvec3> ft = spatially_filtered(test, w, h, ppd);
    const Plane features = flip_detail::feature_error(achromatic(reference), achromatic(test), w, h, ppd);
    std::vector<float> out(reference.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<float>(std::pow(flip_detail::color_error(fr[i], ft[i]), 1.0 - features[i]));
    return out;
}

std::vector<glm::dvec3> linear_pixels(const Image& image, double scale, bool tone_map, FlipToneMapper tm) {
    std::vector<glm::dvec3> out(image.pixels.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        glm::dvec3 p(image.pixels[i]);
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(p[c])) p[c] = 0.0;
        if (tone_map) p = flip_detail::tone_map(scale * p, tm);
        out[i] = glm::clamp(p, 0.0, 1.0);
    }
    return out;
}

// The first error e of `sorted` (ascending) at which the running sum exceeds share * total. Strictly
// exceeds, as FLIP's tool pools: with errors (0.25, 0.25, 0.5) the weighted median is 0.5, not 0.25.
double weighted_percentile(const std::vector<float>& sorted, double total, double share) {
    double running = 0.0;
    for (float e : sorted) {
        running += e;
        if (running > share * total) return e;
    }
    return 0.0;  // all errors 0 (FLIP's tool returns 0 then too)
}

}  // namespace

namespace flip_detail {

void pool(FlipResult& r) {
    double total = 0.0;
    for (std::size_t i = 0; i < r.error.size(); ++i) {
        total += r.error[i];
        if (r.error[i] > r.max) {
            r.max = r.error[i];
            r.max_x = static_cast<int>(i % r.width);
            r.max_y = static_cast<int>(i / r.width);
        }
    }
    r.mean = r.error.empty() ? 0.0 : total / static_cast<double>(r.error.size());
    std::vector<float> sorted = r.error;
    std::sort(sorted.begin(), sorted.end());
    r.weighted_first_quartile = weighted_percentile(sorted, total, 0.25);
    r.weighted_median = weighted_percentile(sorted, total, 0.5);
    r.weighted_third_quartile = weighted_percentile(sorted, total, 0.75);
}

}  // namespace flip_detail

namespace {

// t(x) = (k0 x^2 + k1 x + k2) / (k3 x^2 + k4 x + k5)
struct Rational {
    double k[6];
};
Rational tone_curve(FlipToneMapper tm) {
    if (tm == FlipToneMapper::Reinhard) return {{0.0, 1.0, 0.0, 0.0, 1.0, 1.0}};
    return {{0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.0, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14}};
}

// The x >= 0 with t(x) = v: the positive root of (k0 - v k3) x^2 + (k1 - v k4) x + (k2 - v k5).
double inverse_tone_map(double v, FlipToneMapper tm) {
    const Rational t = tone_curve(tm);
    const double a = t.k[0] - v * t.k[3], b = t.k[1] - v * t.k[4], c = t.k[2] - v * t.k[5];
    if (std::abs(a) < 1e-12) return -c / b;
    return (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

}  // namespace

namespace flip_detail {

double tone_map(double x, FlipToneMapper tm) {
    const Rational t = tone_curve(tm);
    return (t.k[0] * x * x + t.k[1] * x + t.k[2]) / (t.k[3] * x * x + t.k[4] * x + t.k[5]);
}

glm::dvec3 tone_map(const glm::dvec3& rgb, FlipToneMapper tm) {
    // Reinhard scales the whole pixel by its luminance's curve, so hue is kept; on grey both agree.
    if (tm == FlipToneMapper::Reinhard) return rgb / (1.0 + luminance(rgb));
    return {tone_map(rgb.x, tm), tone_map(rgb.y, tm), tone_map(rgb.z, tm)};
}

double luminance(const glm::dvec3& rgb) { return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z; }

double color_error(const glm::dvec3& reference_rgb, const glm::dvec3& test_rgb) {
    using namespace flip_color;
    constexpr double q_c = 0.7, p_c = 0.4, p_t = 0.95;
    auto hunt_lab = [](const glm::dvec3& rgb) { return hunt_adjust(xyz_to_lab(linear_rgb_to_xyz(rgb))); };
    // The largest colour difference in the gamut, pure green against pure blue.
    static const double c_max = std::pow(hyab(hunt_lab({0.0, 1.0, 0.0}), hunt_lab({0.0, 0.0, 1.0})), q_c);
    const double e = std::pow(hyab(hunt_lab(reference_rgb), hunt_lab(test_rgb)), q_c);
    // Small differences are stretched over [0, p_t), large ones compressed into [p_t, 1].
    if (e < p_c * c_max) return p_t / (p_c * c_max) * e;
    return std::min(1.0, p_t + (e - p_c * c_max) / (c_max - p_c * c_max) * (1.0 - p_t));
}

FeatureKernels feature_kernels(double ppd) {
    constexpr double w = 0.082;  // degrees: the feature width the filters are tuned to
    FeatureKernels k;
    k.sigma = 0.5 * w * ppd;
    k.radius = static_cast<int>(std::ceil(3.0 * k.sigma));
    double gauss_sum = 0.0, edge_pos = 0.0, edge_neg = 0.0, point_pos = 0.0, point_neg = 0.0;
    for (int i = -k.radius; i <= k.radius; ++i) {
        const double g = std::exp(-(i * i) / (2.0 * k.sigma * k.sigma));
        const double e = -i * g, p = (i * i / (k.sigma * k.sigma) - 1.0) * g;
        k.gauss.push_back(g);
        k.edge.push_back(e);
        k.point.push_back(p);
        gauss_sum += g;
        (e > 0.0 ? edge_pos : edge_neg) += e;
        (p > 0.0 ? point_pos : point_neg) += p;
    }
    // The 2-D kernel is (x factor) * (y factor); normalising the factors this way normalises the
    // 2-D kernel's positive and negative weights to +1 and -1.
    for (double& g : k.gauss) g /= gauss_sum;
    // (Weights that underflowed to 0, at a few pixels per degree, stay 0.)
    for (double& e : k.edge)
        if (e != 0.0) e /= e > 0.0 ? edge_pos : -edge_neg;
    for (double& p : k.point)
        if (p != 0.0) p /= p > 0.0 ? point_pos : -point_neg;
    return k;
}

std::vector<double> feature_error(const std::vector<double>& reference_y, const std::vector<double>& test_y,
                                  int w, int h, double ppd) {
    const FeatureKernels k = feature_kernels(ppd);
    auto magnitude = [&](const Plane& y, const Kernel& kernel) {
        const Plane dx = filter_separable(y, w, h, kernel, k.gauss), dy = filter_separable(y, w, h, k.gauss, kernel);
        Plane m(y.size());
        for (std::size_t i = 0; i < m.size(); ++i) m[i] = std::hypot(dx[i], dy[i]);
        return m;
    };
    const Plane er = magnitude(reference_y, k.edge), et = magnitude(test_y, k.edge);
    const Plane pr = magnitude(reference_y, k.point), pt = magnitude(test_y, k.point);
    constexpr double q_f = 0.5;
    Plane out(reference_y.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = std::pow(std::max(std::abs(er[i] - et[i]), std::abs(pr[i] - pt[i])) / std::sqrt(2.0), q_f);
    return out;
}

void automatic_exposures(const Image& reference, FlipToneMapper tm, double& start, double& stop) {
    std::vector<double> luminances;
    luminances.reserve(reference.pixels.size());
    double largest = 0.0;
    for (const glm::vec3& p : reference.pixels) {
        double y = luminance(glm::dvec3(p));
        if (!std::isfinite(y)) y = 0.0;
        luminances.push_back(y);
        largest = std::max(largest, y);
    }
    auto mid = luminances.begin() + static_cast<std::ptrdiff_t>(luminances.size() / 2);
    std::nth_element(luminances.begin(), mid, luminances.end());
    double median = luminances.empty() ? 0.0 : *mid;
    if (!(median > 0.0)) {  // more than half black: the median of the lit pixels instead (docs/flip.md)
        std::vector<double> lit;
        for (double y : luminances)
            if (y > 0.0) lit.push_back(y);
        auto m = lit.begin() + static_cast<std::ptrdiff_t>(lit.size() / 2);
        if (!lit.empty()) std::nth_element(lit.begin(), m, lit.end());
        median = lit.empty() ? 0.0 : *m;
    }
    // The exposures at which the brightest pixel, then the median pixel, tone-maps to 0.85.
    const double x = inverse_tone_map(0.85, tm);
    start = largest > 0.0 ? std::log2(x / largest) : 0.0;
    stop = median > 0.0 ? std::log2(x / median) : start;
}

}  // namespace flip_detail

FlipResult flip(const Image& reference, const Image& test, const FlipOptions& options) {
    if (reference.width != test.width || reference.height != test.height)
        throw InputError("image sizes differ: " + std::to_string(reference.width) + "x" +
                         std::to_string(reference.height) + " and " + std::to_string(test.width) + "x" +
                         std::to_string(test.height));
    if (!(options.pixels_per_degree > 0.0)) throw InputError("FLIP pixels per degree must be positive");
    FlipResult r;
    r.width = reference.width;
    r.height = reference.height;
    const double ppd = options.pixels_per_degree;
    if (!options.hdr) {
        r.error = ldr_flip_map(linear_pixels(reference, 1.0, false, options.tone_mapper),
                               linear_pixels(test, 1.0, false, options.tone_mapper), r.width, r.height, ppd);
        flip_detail::pool(r);
        return r;
    }
    double start = 0.0, stop = 0.0;
    flip_detail::automatic_exposures(reference, options.tone_mapper, start, stop);
    if (!std::isnan(options.start_exposure)) start = options.start_exposure;
    if (!std::isnan(options.stop_exposure)) stop = options.stop_exposure;
    if (stop < start) throw InputError("HDR-FLIP stop exposure is below the start exposure");
    const int n = options.exposures > 0 ? options.exposures : std::max(2, static_cast<int>(std::ceil(stop - start)));
    r.start_exposure = start;
    r.stop_exposure = stop;
    r.exposures = n;
    r.error.assign(reference.pixels.size(), 0.0f);
    for (int i = 0; i < n; ++i) {
        const double exposure = n == 1 ? start : start + i * (stop - start) / (n - 1);
        const double scale = std::exp2(exposure);
        const std::vector<float> map =
            ldr_flip_map(linear_pixels(reference, scale, true, options.tone_mapper),
                         linear_pixels(test, scale, true, options.tone_mapper), r.width, r.height, ppd);
        for (std::size_t p = 0; p < map.size(); ++p) r.error[p] = std::max(r.error[p], map[p]);
    }
    flip_detail::pool(r);
    return r;
}

}  // namespace sweeptrace

namespace sweeptrace {

double flip_largest_window_mean(const FlipResult& r, int window) {
    const int wx = std::min(window, r.width), wy = std::min(window, r.height);
    if (wx <= 0 || wy <= 0) return 0.0;
    // Summed-area table, one row and column of zeros in front.
    const int W = r.width + 1;
    std::vector<double> sat(static_cast<std::size_t>(W) * (r.height + 1), 0.0);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x)
            sat[std::size_t(y + 1) * W + x + 1] = r.error[std::size_t(y) * r.width + x] + sat[std::size_t(y) * W + x + 1] +
                                                   sat[std::size_t(y + 1) * W + x] - sat[std::size_t(y) * W + x];
    double best = 0.0;
    for (int y = 0; y + wy <= r.height; ++y)
        for (int x = 0; x + wx <= r.width; ++x) {
            const double s = sat[std::size_t(y + wy) * W + x + wx] - sat[std::size_t(y) * W + x + wx] -
                             sat[std::size_t(y + wy) * W + x] + sat[std::size_t(y) * W + x];
            best = std::max(best, s / (wx * wy));
        }
    return best;
}

Image flip_heatmap(const FlipResult& r) {
    static const glm::dvec3 stops[] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    Image out(r.width, r.height);
    for (std::size_t i = 0; i < r.error.size(); ++i) {
        const double t = std::clamp(static_cast<double>(r.error[i]), 0.0, 1.0) * 5.0;
        const int k = std::min(static_cast<int>(t), 4);
        const glm::dvec3 c = glm::mix(stops[k], stops[k + 1], t - k);
        // write_image encodes to sRGB: decode so the PNG holds exactly the ramp's colours.
        for (int ch = 0; ch < 3; ++ch)
            out.pixels[i][ch] = static_cast<float>(c[ch] <= 0.04045 ? c[ch] / 12.92 : std::pow((c[ch] + 0.055) / 1.055, 2.4));
    }
    return out;
}

}  // namespace sweeptrace

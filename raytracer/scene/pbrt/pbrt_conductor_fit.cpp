#include "raytracer/scene/pbrt/pbrt_conductor_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "raytracer/scene/pbrt/pbrt_spectra.hpp"

namespace sweeptrace::pbrt {

namespace {

constexpr int kFirstNm = 380, kLastNm = 780;  // the weights' range, every nm
constexpr int kThetaSteps = 90;               // midpoints of one-degree steps

// The textbook form with complex n cos(theta_t) = sqrt(n^2 - sin^2), independent of the
// renderer's real closed form (render/materials/bsdf_conductor.cpp), as the Python tool's.
double fresnel_complex(double cos_i, double eta, double k) {
    using C = std::complex<double>;
    const C n2 = C(eta, k) * C(eta, k);
    const C ct = std::sqrt(n2 - (1.0 - cos_i * cos_i));
    const C rs = (cos_i - ct) / (cos_i + ct);
    const C rp = (n2 * cos_i - ct) / (n2 * cos_i + ct);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

using Weights = std::array<std::vector<double>, 3>;

// w_c(lambda): each channel of linear sRGB from the CIE functions, normalised to sum 1.
const Weights& channel_weights() {
    static const Weights weights = [] {
        Weights w;
        for (int nm = kFirstNm; nm <= kLastNm; ++nm) {
            const glm::dvec3 rgb = linear_srgb_from_xyz(cie_xyz_1931(nm));
            for (int c = 0; c < 3; ++c) w[c].push_back(rgb[c]);
        }
        for (std::vector<double>& channel : w) {
            double total = 0.0;
            for (double v : channel) total += v;
            for (double& v : channel) v /= total;
        }
        return w;
    }();
    return weights;
}

struct Thetas {
    std::array<double, kThetaSteps> cos, sin;
};

const Thetas& thetas() {
    static const Thetas t = [] {
        Thetas out{};
        for (int d = 0; d < kThetaSteps; ++d) {
            out.cos[d] = std::cos((d + 0.5) * (std::numbers::pi / 180.0));
            out.sin[d] = std::sin((d + 0.5) * (std::numbers::pi / 180.0));
        }
        return out;
    }();
    return t;
}

struct Spectral {
    std::vector<std::array<double, kThetaSteps>> at_theta;  // per wavelength, R(theta_t)
    std::vector<double> normal;                             // per wavelength, R(0)
};

Spectral spectral_reflectance(const std::vector<double>& eta_pairs, const std::vector<double>& k_pairs) {
    Spectral s;
    for (int nm = kFirstNm; nm <= kLastNm; ++nm) {
        const double eta = std::max(sampled_at(eta_pairs, nm), 1e-4), k = std::max(sampled_at(k_pairs, nm), 0.0);
        std::array<double, kThetaSteps> r{};
        for (int t = 0; t < kThetaSteps; ++t) r[t] = fresnel_complex(thetas().cos[t], eta, k);
        s.at_theta.push_back(r);
        s.normal.push_back(fresnel_complex(1.0, eta, k));
    }
    return s;
}

struct ChannelFit {
    double eta, k;
};

// (eta, k) exact at normal incidence `r0`, eta minimising the cosine-weighted squared error to
// `target` (grid, then golden section: tools/conductor_rgb.py's steps and constants).
ChannelFit fit_channel(const std::array<double, kThetaSteps>& target, double r0) {
    r0 = std::clamp(r0, 0.0, 0.9999);
    auto k_for = [&](double e, double& k) {
        const double k2 = (r0 * (e + 1) * (e + 1) - (e - 1) * (e - 1)) / (1 - r0);
        if (!(k2 >= 0.0)) return false;
        k = std::sqrt(k2);
        return true;
    };
    auto cost = [&](double e) {
        double k = 0.0, sum = 0.0;
        if (!k_for(e, k)) return std::numeric_limits<double>::infinity();
        for (int t = 0; t < kThetaSteps; ++t) {
            const double c = thetas().cos[t], diff = fresnel_complex(c, e, k) - target[t];
            sum += c * thetas().sin[t] * (diff * diff);
        }
        return sum;
    };
    double best = 0.01, best_cost = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 700; ++i)
        if (const double e = 0.01 * std::pow(1.01, i), ce = cost(e); ce < best_cost) best = e, best_cost = ce;
    double lo = best / 1.01, hi = best * 1.01;
    for (int i = 0; i < 60; ++i) {
        const double a = hi - (hi - lo) * 0.618034, b = lo + (hi - lo) * 0.618034;
        if (cost(a) < cost(b)) hi = b;
        else lo = a;
    }
    ChannelFit fit{0.5 * (lo + hi), 0.0};
    if (!k_for(fit.eta, fit.k)) {  // a dielectric's channel
        const double s = std::sqrt(r0);
        fit = {(1 + s) / (1 - s), 0.0};
    }
    return fit;
}

}  // namespace

ConductorRgb fit_conductor_rgb(const std::vector<double>& eta_pairs, const std::vector<double>& k_pairs) {
    const Spectral s = spectral_reflectance(eta_pairs, k_pairs);
    ConductorRgb out{};
    for (int c = 0; c < 3; ++c) {
        const std::vector<double>& w = channel_weights()[c];
        std::array<double, kThetaSteps> target{};
        double r0 = 0.0;
        for (std::size_t i = 0; i < w.size(); ++i) {
            for (int t = 0; t < kThetaSteps; ++t) target[t] += w[i] * s.at_theta[i][t];
            r0 += w[i] * s.normal[i];
        }
        const ChannelFit fit = fit_channel(target, r0);
        out.eta[c] = fit.eta;
        out.k[c] = fit.k;
        out.normal_reflectance[c] = r0;
    }
    return out;
}

bool covers_visible(const std::vector<double>& pairs) {
    return pairs.size() >= 2 && pairs.front() <= kFirstNm && pairs[pairs.size() - 2] >= kLastNm;
}

}  // namespace sweeptrace::pbrt

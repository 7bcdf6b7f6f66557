#pragma once
// The pdf-consistency test of pbrt-v4's and Mitsuba's BSDF test suites: sample a material's
// directions from a fixed wo, bin them on the sphere (theta and phi in equal steps), integrate
// eval_bsdf's density over every bin, and compare the histogram with the expected counts by
// Pearson's chi-square test. Bins expected to hold fewer than 5 samples are pooled (the test's
// usual validity rule), and one more bin holds everything that is not a non-delta direction:
// failed samples and delta-lobe samples, expected N (1 - integral of the pdf). A wrong density,
// a wrong lobe probability or a sampler that drifts from eval shows as a tiny p-value.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/sampling/random.hpp"

namespace sweeptrace::test {

// Regularized upper incomplete gamma Q(a, x) = Gamma(a, x) / Gamma(a): the series of P for
// x < a + 1, Lentz's continued fraction for Q otherwise (both converge fast there), to ~1e-12.
inline double gamma_q(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000 && std::abs(term) > 1e-15 * std::abs(sum); ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(log_prefix);
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(log_prefix) * h;
}

struct ChiSquareResult {
    double statistic = 0.0;
    int dof = 0;
    double p_value = 0.0;
    double pdf_integral = 0.0;  // the density's integral over the sphere (the non-delta share)
    std::string summary() const {
        std::ostringstream s;
        s << "chi2 " << statistic << " dof " << dof << " p " << p_value << " (pdf integral " << pdf_integral << ")";
        return s.str();
    }
};

// Significance per test: 0.01 for the whole file, split over `tests` by Sidak's correction.
inline double chi_square_alpha(int tests) { return 1.0 - std::pow(1.0 - 0.01, 1.0 / tests); }

inline ChiSquareResult chi_square_bsdf(const Material& m, const ShadingContext& ctx, int samples, std::uint64_t seed) {
    constexpr int n_theta = 36, n_phi = 72;
    const double d_theta = M_PI / n_theta, d_phi = 2.0 * M_PI / n_phi;
    std::vector<double> observed(n_theta * n_phi + 1, 0.0), expected(n_theta * n_phi + 1, 0.0);
    const auto to_world = [&](double theta, double phi) {
        const glm::vec3 local(static_cast<float>(std::sin(theta) * std::cos(phi)),
                              static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)));
        return ctx.frame.to_world(local);
    };
    Rng rng(seed, 0, 0);
    for (int i = 0; i < samples; ++i) {
        BsdfSample s;
        const float u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        if (!sample_bsdf(m, ctx, u0, u1, u2, s) || s.delta) {
            observed.back() += 1.0;
            continue;
        }
        const glm::vec3 l = ctx.frame.to_local(s.wi);
        const double theta = std::acos(std::clamp(static_cast<double>(l.z), -1.0, 1.0));
        double phi = std::atan2(static_cast<double>(l.y), static_cast<double>(l.x));
        if (phi < 0.0) phi += 2.0 * M_PI;
        const int it = std::min(n_theta - 1, static_cast<int>(theta / d_theta));
        const int ip = std::min(n_phi - 1, static_cast<int>(phi / d_phi));
        observed[static_cast<std::size_t>(it * n_phi + ip)] += 1.0;
    }
    ChiSquareResult r;
    for (int it = 0; it < n_theta; ++it)
        for (int ip = 0; ip < n_phi; ++ip) {
            // Midpoint rule with the sin(theta) Jacobian on 4 x 4 and 8 x 8 sub-grids; again on
            // 64 x 64 where they disagree by more than 1e-3, or where the 8 x 8 grid sees the
            // density both zero and not: an edge of its support crosses the bin (the density of
            // a rough refraction, for one, jumps from 0 where the microfacet normal reaches the
            // horizon), where the midpoint rule's error is of the order of one sub-row.
            bool edge = false;
            const auto bin_integral = [&](int sub) {
                double sum = 0.0;
                int zeros = 0;
                for (int a = 0; a < sub; ++a)
                    for (int b = 0; b < sub; ++b) {
                        const double theta = (it + (a + 0.5) / sub) * d_theta, phi = (ip + (b + 0.5) / sub) * d_phi;
                        const double pdf = eval_bsdf(m, ctx, to_world(theta, phi)).pdf;
                        zeros += pdf == 0.0;
                        sum += pdf * std::sin(theta);
                    }
                edge = zeros > 0 && zeros < sub * sub;
                return sum * d_theta * d_phi / (sub * sub);
            };
            const double coarse = bin_integral(4);
            double integral = bin_integral(8);
            if (edge || std::abs(integral - coarse) > 1e-3 * integral) integral = bin_integral(64);
            expected[static_cast<std::size_t>(it * n_phi + ip)] = integral * samples;
            r.pdf_integral += integral;
        }
    expected.back() = std::max(0.0, 1.0 - r.pdf_integral) * samples;
    // Pool the bins expected below 5, smallest first, into one (adding more until the pool is
    // expected to hold 5): samples where the density says there are almost none land there.
    std::vector<std::size_t> order(expected.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
    double pooled_obs = 0.0, pooled_exp = 0.0;
    std::size_t k = 0;
    for (; k < order.size() && (expected[order[k]] < 5.0 || (pooled_exp > 0.0 && pooled_exp < 5.0)); ++k) {
        pooled_obs += observed[order[k]];
        pooled_exp += expected[order[k]];
    }
    const auto add = [&](double o, double e) { r.statistic += (o - e) * (o - e) / e; };
    int bins = 0;
    if (pooled_exp > 0.0) {
        add(pooled_obs, pooled_exp);
        ++bins;
    } else if (pooled_obs > 0.0) {
        r.statistic = INFINITY;  // samples where the density is exactly zero
    }
    for (; k < order.size(); ++k, ++bins) add(observed[order[k]], expected[order[k]]);
    r.dof = bins - 1;
    r.p_value = gamma_q(0.5 * r.dof, 0.5 * r.statistic);
    return r;
}

}  // namespace sweeptrace::test

namespace sweeptrace::test {

// Samples whose density or weight differs from eval_bsdf's in the sampled direction by more than
// 1e-3 relative (sampling and eval reach the half vector by different float paths; see the
// bound argued in test_render_bsdf.cpp), with a 1e-5 absolute margin on the weight for grazing
// directions whose cosine rounds to 0 on the way to world space and back.
inline int sample_eval_mismatches(const Material& m, const ShadingContext& ctx, int samples, std::uint64_t seed) {
    Rng rng(seed, 1, 0);
    int bad = 0;
    for (int i = 0; i < samples; ++i) {
        BsdfSample s;
        const float u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        if (!sample_bsdf(m, ctx, u0, u1, u2, s) || s.delta) continue;
        const BsdfEval e = eval_bsdf(m, ctx, s.wi);
        if (e.pdf == 0.0f) {
            bad += max_component(s.weight) >= 1e-5f;
            continue;
        }
        const bool pdf_ok = std::abs(e.pdf - s.pdf) <= 1e-3f * s.pdf;
        bool weight_ok = true;
        for (int c = 0; c < 3; ++c)
            weight_ok = weight_ok && std::abs(e.f_cos[c] / e.pdf - s.weight[c]) <= 1e-3f * s.weight[c] + 1e-5f;
        bad += !(pdf_ok && weight_ok);
    }
    return bad;
}

}  // namespace sweeptrace::test

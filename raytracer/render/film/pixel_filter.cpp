#include "raytracer/render/film/pixel_filter.hpp"

#include <algorithm>
#include <cmath>

namespace sweeptrace {

namespace {

using Type = FilterSpec::Type;

// Mitchell-Netravali on t in [0, 2] (times 6), its pieces' antiderivatives from 0, and the root
// x0 of the outer piece's linear factor, after which it is negative.
struct Mitchell {
    double b, c;
    double inner(double t) const { return ((12 - 9 * b - 6 * c) * t + (-18 + 12 * b + 6 * c)) * t * t + (6 - 2 * b); }
    double outer(double t) const {
        return (((-b - 6 * c) * t + (6 * b + 30 * c)) * t + (-12 * b - 48 * c)) * t + (8 * b + 24 * c);
    }
    double inner_int(double t) const {
        return (((12 - 9 * b - 6 * c) / 4 * t + (-18 + 12 * b + 6 * c) / 3) * t * t + (6 - 2 * b)) * t;
    }
    double outer_int(double t) const {
        return ((((-b - 6 * c) / 4 * t + (6 * b + 30 * c) / 3) * t + (-12 * b - 48 * c) / 2) * t + (8 * b + 24 * c)) * t;
    }
    double root() const { return b + 6 * c > 0 ? std::clamp((2 * b + 6 * c) / (b + 6 * c), 1.0, 2.0) : 2.0; }
    double m(double t) const {
        t = std::abs(t);
        return t < 1 ? inner(t) / 6 : t < 2 ? outer(t) / 6 : 0.0;
    }
    // int_0^t |M| for t in [0, 2].
    double abs_int(double t) const {
        if (t <= 1) return inner_int(t) / 6;
        const double x0 = root();
        const double at1 = inner_int(1) / 6;
        if (t <= x0) return at1 + (outer_int(t) - outer_int(1)) / 6;
        return at1 + (outer_int(x0) - outer_int(1)) / 6 - (outer_int(t) - outer_int(x0)) / 6;
    }
};

constexpr double kSqrtHalfPi = 1.2533141373155002512;  // sqrt(pi / 2)

}  // namespace

PixelFilter::PixelFilter(const FilterSpec& spec) : spec_(spec) {
    const double r = spec.radius;
    switch (spec.type) {
    case Type::Box: abs_total_ = signed_total_ = 2 * r; break;
    case Type::Tent: abs_total_ = signed_total_ = r * r; break;
    case Type::Gaussian: abs_total_ = signed_total_ = cdf_abs(r); break;
    case Type::Mitchell: {
        const Mitchell mi{spec.b, spec.c};
        abs_total_ = r * mi.abs_int(2.0);                    // (r / 2) * 2 int_0^2 |M|
        signed_total_ = r * (mi.inner_int(1) + mi.outer_int(2) - mi.outer_int(1)) / 6;  // = r / 2
        break;
    }
    }
    const double k = abs_total_ / signed_total_;
    weight_ = static_cast<float>(k * k);
}

double PixelFilter::eval(double x) const {
    const double r = spec_.radius;
    if (!(std::abs(x) <= r)) return 0.0;
    switch (spec_.type) {
    case Type::Box: return 1.0;
    case Type::Tent: return r - std::abs(x);
    case Type::Gaussian: {
        const double s2 = 2.0 * double(spec_.sigma) * spec_.sigma;
        return std::max(0.0, std::exp(-x * x / s2) - std::exp(-r * r / s2));
    }
    case Type::Mitchell: return Mitchell{spec_.b, spec_.c}.m(2.0 * x / r);
    }
    return 0.0;
}

double PixelFilter::cdf_abs(double x) const {
    const double r = spec_.radius;
    x = std::clamp(x, -r, r);
    switch (spec_.type) {
    case Type::Box: return x + r;
    case Type::Tent: return x <= 0 ? 0.5 * (x + r) * (x + r) : r * r - 0.5 * (r - x) * (r - x);
    case Type::Gaussian: {
        const double s = spec_.sigma, k = 1.0 / (s * std::sqrt(2.0));
        return s * kSqrtHalfPi * (std::erf(x * k) + std::erf(r * k)) - std::exp(-r * r / (2 * s * s)) * (x + r);
    }
    case Type::Mitchell: {
        const Mitchell mi{spec_.b, spec_.c};
        const double half = (r / 2) * mi.abs_int(2.0), part = (r / 2) * mi.abs_int(2.0 * std::abs(x) / r);
        return x < 0 ? half - part : half + part;
    }
    }
    return 0.0;
}

// The x in [-r, r] where cdf_abs(x) = target: Newton steps (derivative |f|) kept inside a
// bisection bracket, so it converges for any monotone CDF; stops when the bracket is below a
// float ulp of r or after 64 steps.
double PixelFilter::invert(double target) const {
    const double r = spec_.radius;
    double lo = -r, hi = r, x = 0.0;
    for (int i = 0; i < 64 && hi - lo > 1e-9 * r; ++i) {
        const double g = cdf_abs(x) - target;
        if (g == 0.0) return x;
        (g < 0 ? lo : hi) = x;
        const double d = std::abs(eval(x));
        const double newton = d > 0 ? x - g / d : lo - 1.0;
        x = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
    }
    return x;
}

float PixelFilter::sample_axis(float u, float& sign) const {
    const double r = spec_.radius;
    sign = 1.0f;
    switch (spec_.type) {
    case Type::Box: return 0.0f;  // handled in sample()
    case Type::Tent:
        return static_cast<float>(u < 0.5f ? -r + r * std::sqrt(2.0 * u) : r - r * std::sqrt(2.0 - 2.0 * u));
    case Type::Gaussian:
    case Type::Mitchell: {
        const double x = invert(u * abs_total_);
        if (eval(x) < 0) sign = -1.0f;
        return static_cast<float>(x);
    }
    }
    return 0.0f;
}

FilmOffset PixelFilter::sample(float u1, float u2) const {
    FilmOffset o;
    if (spec_.type == Type::Box) {
        const float r = spec_.radius;
        o.dx = (0.5f - r) + 2.0f * r * u1;  // r = 0.5: exactly u1
        o.dy = (0.5f - r) + 2.0f * r * u2;
        return o;
    }
    float sx = 1.0f, sy = 1.0f;
    o.dx = 0.5f + sample_axis(u1, sx);
    o.dy = 0.5f + sample_axis(u2, sy);
    o.weight = sx * sy * weight_;
    return o;
}

}  // namespace sweeptrace

#pragma once
// Pixel reconstruction by filter importance sampling (pbrt-v4's way, Ernst et al. 2006): each
// camera sample's film position is drawn from the filter itself around the pixel's centre, so
// the pixel is the plain mean of its samples, each sample belongs to one pixel, and any split of
// the samples (passes, threads) gives the same image bit for bit.
//
// The filters are separable, f(x) f(y) for offsets in pixels, and each axis is drawn by exactly
// inverting the CDF of |f| (so the density sampled with is |f| / int |f|, not a table of it):
// - box of radius r: f = 1 on [-r, r]; x = (2u - 1) r, evaluated as an offset 0.5 - r + 2 r u
//   from the pixel's corner, which for the default r = 0.5 is u itself (today's jitter, bit for
//   bit);
// - tent of radius r: f = max(0, r - |x|); closed-form inverse;
// - Gaussian of radius r and sigma s: f = max(0, exp(-x^2 / 2 s^2) - exp(-r^2 / 2 s^2)) (pbrt's
//   form, continuous at the radius); CDF by erf, inverted by safeguarded Newton in double;
// - Mitchell-Netravali (B, C) of radius r: f(x) = M(2 x / r) with M the 1988 cubic on [-2, 2];
//   it is negative on x0 < |t| < 2, t = 2 x / r, x0 = (2 B + 6 C) / (B + 6 C) (M has a double
//   root at 2, so on [1, 2] 6 M = (t - 2)^2 (-(B + 6 C) t + 2 B + 6 C)); M >= 0 on [0, 1] for
//   B, C in [0, 1]. Inverted like the Gaussian.
// Weight: sign(f(x) f(y)) (int |f| / int f)^2, constant in magnitude: exactly 1 for box, tent and
// Gaussian; for Mitchell the sign of the lobe carries through, so the plain mean of weight x
// radiance estimates the filtered image  int f L / int f  without bias.
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

struct FilmOffset {
    float dx = 0.5f, dy = 0.5f;  // from the pixel's top-left corner, in pixels (x right, y down)
    float weight = 1.0f;
};

class PixelFilter {
public:
    explicit PixelFilter(const FilterSpec& spec = {});

    FilmOffset sample(float u1, float u2) const;

    // The 1D filter and the integrals the sampling uses, for tests: f(x) at offset x from the
    // centre; int_{-r}^{x} |f|; int |f| and int f over [-r, r].
    double eval(double x) const;
    double cdf_abs(double x) const;
    double integral_abs() const { return abs_total_; }
    double integral() const { return signed_total_; }

private:
    float sample_axis(float u, float& sign) const;  // offset from the centre
    double invert(double target) const;

    FilterSpec spec_;
    double abs_total_ = 1.0, signed_total_ = 1.0;
    float weight_ = 1.0f;  // (int |f| / int f)^2
};

}  // namespace sweeptrace

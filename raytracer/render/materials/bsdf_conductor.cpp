// The conductor: GGX reflection (render/materials/bsdf_ggx_reflection.hpp) with the exact Fresnel term of a
// complex index of refraction.
//
// The Fresnel term, derived. Light from a medium of index 1 meets a conductor of relative index
// n = eta + i k at an angle theta (c = cos theta, s2 = sin^2 theta). Snell's law holds with complex
// angles; the only quantity the amplitudes need is u = n cos theta_t = sqrt(n^2 - s2) (principal
// root, Re u >= 0, which is the decaying wave). The amplitudes for s and p polarisation are
//   r_s = (c - u) / (c + u),        r_p = (n^2 c - u) / (n^2 c + u).
// With n^2 = u^2 + s2, n^2 c - u = c u^2 + c s2 - u = (c - u)(s2 - u c) (expand: c s2 - u c^2 -
// u s2 + u^2 c, and c^2 + s2 = 1), and likewise n^2 c + u = (c + u)(s2 + u c), so
//   r_p = r_s (s2 - u c) / (s2 + u c).
// Writing u = a + i b, with w = n^2 - s2 = (eta^2 - k^2 - s2) + i 2 eta k and |w| = a^2 + b^2:
//   R_s = |r_s|^2 = ((c - a)^2 + b^2) / ((c + a)^2 + b^2)
//   R_p = R_s ((s2 - a c)^2 + (b c)^2) / ((s2 + a c)^2 + (b c)^2),   R = (R_s + R_p) / 2.
// Normal incidence (c = 1, u = n): R = ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2). Grazing (c = 0):
// R_s = R_p = 1. k = 0 with eta < 1 past the critical angle: w < 0, a = 0, R_s = R_p = 1 (total
// internal reflection), so the dielectric is the k = 0 case.
// Numerics: a and b come from |w| and Re w by the half-angle formulas, each taken from the sum
// without cancellation (a^2 = (|w| + Re w) / 2 when Re w >= 0, else b^2 = (|w| - Re w) / 2) and
// the other from 2 a b = Im w; the numerators are sums of squares, never differences, so the
// result keeps float's relative precision (the test measures < 2e-6 over eta, k in [0.05, 20]).
#include <algorithm>
#include <cmath>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/materials/bsdf_ggx_reflection.hpp"

namespace sweeptrace {

float fresnel_conductor(float cos_i, float eta, float k) {
    const float c = std::clamp(cos_i, 0.0f, 1.0f);
    const float s2 = 1.0f - c * c;
    const float re = eta * eta - k * k - s2, im = 2.0f * eta * k;
    const float mod = std::hypot(re, im);
    float a = 0.0f, b = 0.0f;
    if (re >= 0.0f) {
        a = std::sqrt(0.5f * (mod + re));
        b = a > 0.0f ? im / (2.0f * a) : 0.0f;
    } else {
        b = std::sqrt(0.5f * (mod - re));
        a = im / (2.0f * b);
    }
    const float den_s = (c + a) * (c + a) + b * b;
    if (den_s == 0.0f) return 1.0f;  // c = 0 and n = 1: the grazing limit
    const float rs = ((c - a) * (c - a) + b * b) / den_s;
    const float bc = b * c;
    const float rp = rs * ((s2 - a * c) * (s2 - a * c) + bc * bc) / ((s2 + a * c) * (s2 + a * c) + bc * bc);
    return 0.5f * (rs + rp);
}

glm::vec3 fresnel_conductor(float cos_i, const glm::vec3& eta, const glm::vec3& k) {
    return {fresnel_conductor(cos_i, eta.x, k.x), fresnel_conductor(cos_i, eta.y, k.y),
            fresnel_conductor(cos_i, eta.z, k.z)};
}

BsdfEval eval_conductor(const MaterialParameters& m, const ShadingContext& ctx, const glm::vec3& wi) {
    return ggx_reflection::eval(m, ctx, wi, [&](float cos_d) { return m.albedo * fresnel_conductor(cos_d, m.eta, m.k); });
}

bool sample_conductor(const MaterialParameters& m, const ShadingContext& ctx, float u1, float u2, BsdfSample& out) {
    return ggx_reflection::sample(m, ctx, u1, u2, out,
                                  [&](float cos_d) { return m.albedo * fresnel_conductor(cos_d, m.eta, m.k); });
}

}  // namespace sweeptrace

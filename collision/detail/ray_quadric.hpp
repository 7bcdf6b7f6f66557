#pragma once
// Shared numerics of the curved ray tests (sphere, cylinder side, capsule, ellipsoid): the roots
// of |f + t d|^2 = r^2 in 2D or 3D by the stable quadratic, the re-projection of a point onto a
// sphere/circle, and an orthonormal basis around an axis. See intersect_sphere.cpp for the
// method and its error analysis; the other curved shapes state their bounds in terms of it.
#include <cmath>
#include <numbers>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "collision/float_error.hpp"
#include "collision/ray.hpp"

namespace collision::detail {

// Roots t0 <= t1 of |f + t d|^2 = r^2 (f = origin - centre), false if the line misses or the
// input is degenerate (d = 0, or NaN/overflow anywhere). With a = d.d, b = f.d:
// disc / a = (r - |l|)(r + |l|) with l = f - (b / a) d, the closest-approach offset, so the
// discriminant does not cancel for far origins; q = -(b + sign(b) sqrt(disc)), t0 = c / q,
// t1 = q / a take each root from a same-signed sum. A tangent line gives t0 == t1.
template <typename Vec>
inline bool stable_roots(const Vec& f, const Vec& d, float r, float& t0, float& t1) {
    const float a = glm::dot(d, d);
    if (!(a > 0.0f) || !std::isfinite(a)) return false;
    const float b = glm::dot(f, d);
    const Vec l = f - (b / a) * d;
    const float l_len = std::sqrt(glm::dot(l, l));
    const float disc_over_a = (r - l_len) * (r + l_len);
    if (!(disc_over_a >= 0.0f) || !std::isfinite(disc_over_a)) return false;
    const float c = glm::dot(f, f) - r * r;
    if (!std::isfinite(c)) return false;
    const float q = -(b + std::copysign(std::sqrt(a * disc_over_a), b));
    if (q == 0.0f) {  // only when b == 0 and disc == 0: the origin is the tangent point
        t0 = t1 = 0.0f;
        return true;
    }
    t0 = c / q;
    t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

// The nearer of two sorted roots strictly inside (tmin, tmax); NaN never qualifies.
inline bool pick_root(float t0, float t1, const Ray& ray, float& t) {
    if (t0 > ray.tmin && t0 < ray.tmax) {
        t = t0;
    } else if (t1 > ray.tmin && t1 < ray.tmax) {
        t = t1;
    } else {
        return false;
    }
    return true;
}

// Moves p onto the sphere (centre, r) along the ray from the centre: point = centre + r n with
// n = normalize(p - centre). normalize() and the scaling by r cost gamma(6) |r n_i|, adding
// the centre one rounding of |point_i|, hence point_error = gamma(7) |r n| + gamma(2) |point|
// per axis, a bound of the distance to a point exactly on the sphere. False when p - centre
// is 0 or overflows (radius below sqrt(min float) or coordinates beyond ~1e18).
inline bool reproject_on_sphere(const glm::vec3& p, const glm::vec3& center, float r, glm::vec3& n,
                                glm::vec3& point, glm::vec3& point_error) {
    const glm::vec3 v = p - center;
    const float v_len2 = glm::dot(v, v);
    if (!(v_len2 > 0.0f) || !std::isfinite(v_len2)) return false;
    n = v * (1.0f / std::sqrt(v_len2));
    const glm::vec3 w = r * n;
    point = center + w;
    point_error = gamma(7) * glm::abs(w) + gamma(2) * glm::abs(point);
    return true;
}

// Angle in [0, 1) of (x, y) around the origin: atan2 / 2 pi, wrapped.
inline float turn_fraction(float y, float x) {
    float phi = std::atan2(y, x);
    if (phi < 0.0f) phi += 2.0f * std::numbers::pi_v<float>;
    return phi * (0.5f * std::numbers::inv_pi_v<float>);
}

// Spherical (phi / 2 pi, theta / pi) of a unit normal, phi = atan2(n.z, n.x), theta = acos(n.y).
inline glm::vec2 sphere_uv(const glm::vec3& n) {
    return {turn_fraction(n.z, n.x), std::acos(std::fmin(1.0f, std::fmax(-1.0f, n.y))) * std::numbers::inv_pi_v<float>};
}

// Orthonormal basis with `n` (unit) as its second vector: returns (t, b) with (t, n, b)
// right-handed, t x n = b. Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017):
// branchless apart from the sign, no division by a small number, continuous except at n.z = 0's
// sign flip.
inline void basis_around(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float k = n.x * n.y * a;
    // Duff's (b1, b2) form a right-handed frame (b1, b2, n); we want n as the middle axis.
    const glm::vec3 b1(1.0f + sign * n.x * n.x * a, sign * k, -sign * n.x);
    const glm::vec3 b2(k, sign + n.y * n.y * a, -n.y);
    // (b1, b2, n) right-handed  =>  (b2, n, b1) right-handed: b2 x n = b1.
    t = b2;
    b = b1;
}

}  // namespace collision::detail

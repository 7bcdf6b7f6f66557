// Ray-sphere intersection, robust default (thesis §3.1 "sphere-sphere, continuous" as a ray cast).
//
// Method. With f = o - c, a = d.d, b = f.d (half the textbook b) the roots of
// a t^2 + 2 b t + (f.f - r^2) = 0 are wanted. Two cancellations ruin the textbook form for far
// origins and huge spheres (see collision/thesis/intersect_sphere.cpp):
//  - the discriminant b^2 - a (f.f - r^2) subtracts two numbers of size |f|^2 |d|^2 when only
//    r^2 - |l|^2 survives. We compute it from the closest-approach offset
//    l = f - (b / a) d (the perpendicular part of f, Ray Tracing Gems ch. 7, pbrt-v4) as
//    disc = a (r - |l|)(r + |l|), whose error is relative to r |l|, not to |f|^2;
//  - -b +- sqrt(disc) cancels for one root: q = -(b + sign(b) sqrt(disc)), t0 = c / q,
//    t1 = q / a takes each root from a sum of same-signed terms.
// The hit point o + t d is then re-projected on the sphere, p = c + r normalize(p - c), which
// puts it on the surface up to a few roundings however inaccurate t was (pbrt-v4 §6.8.5).
//
// Error bounds (float, inputs exact floats; eps = 2^-24, gamma(n) = n eps / (1 - n eps)).
//  t:  |t - t_exact| <= gamma(32) ((|f| + r)(1 + r / h) / |d| + |t|), where h = sqrt(r^2 - |l|^2)
//      is the exact half-chord. Counting roundings: f carries eps |f|, b gamma(4) |f||d|,
//      b / a and l gamma(10) |f|, so r^2 - |l|^2 carries about gamma(12) r (|f| + r); the root
//      divides that by 2 h (the derivative of the quadratic at the root) and by |d|; the final
//      division/sum add gamma(3) |t|. That gives gamma(16); the stated bound doubles it so the
//      rough count stays conservative. The factor r / h is the real conditioning of a grazing
//      hit: as the ray becomes tangent, no float method can pin t down better.
//  point: per axis, |point_i - s_i| <= point_error_i for a point s exactly on the sphere:
//      normalize() and the scaling by r cost gamma(6) |r n_i|, adding c one more rounding of
//      |point_i|; we store gamma(7) |r n_i| + gamma(2) |point_i|. This bounds the distance to
//      the *surface* (what offsetting the next ray needs); along the surface the point is as
//      good as t (bound above times |d|).
//  normal: unit to gamma(6), outward (c -> point), also for rays starting inside.
//  uv: (phi / 2 pi, theta / pi), phi = atan2(n.z, n.x) in [0, 2 pi), theta = acos(n.y).
// Degenerate input: radius <= 0, NaN or infinite radius/centre/origin/direction, zero direction,
// or coordinates so large that squares overflow float (beyond ~1e18) give false.
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"

namespace collision {

bool intersect(const Ray& ray, const Sphere& s, RayHit& hit) {
    const float r = s.radius;
    if (!(r > 0.0f) || !std::isfinite(r)) return false;
    const glm::vec3 f = ray.origin - s.center;
    const glm::vec3& d = ray.dir;
    const float a = glm::dot(d, d);
    if (!(a > 0.0f) || !std::isfinite(a)) return false;
    const float b = glm::dot(f, d);
    const glm::vec3 l = f - (b / a) * d;
    const float l_len = std::sqrt(glm::dot(l, l));
    const float disc_over_a = (r - l_len) * (r + l_len);
    // Written so NaN (from a non-finite origin or centre) is a miss.
    if (!(disc_over_a >= 0.0f) || !std::isfinite(disc_over_a)) return false;
    const float root = std::sqrt(a * disc_over_a);
    const float c = glm::dot(f, f) - r * r;
    if (!std::isfinite(c)) return false;
    const float q = -(b + std::copysign(root, b));
    float t0 = 0.0f, t1 = 0.0f;
    if (q != 0.0f) {  // q == 0 only when b == 0 and disc == 0: the origin is the tangent point
        t0 = c / q;
        t1 = q / a;
        if (t0 > t1) std::swap(t0, t1);
    }
    float t;
    if (t0 > ray.tmin && t0 < ray.tmax) {
        t = t0;
    } else if (t1 > ray.tmin && t1 < ray.tmax) {
        t = t1;
    } else {
        return false;
    }

    const glm::vec3 v = ray.at(t) - s.center;
    const float v_len2 = glm::dot(v, v);
    if (!(v_len2 > 0.0f) || !std::isfinite(v_len2)) return false;  // r below sqrt(min float)
    const glm::vec3 n = v * (1.0f / std::sqrt(v_len2));
    const glm::vec3 w = r * n;
    hit.t = t;
    hit.point = s.center + w;
    hit.point_error = gamma(7) * glm::abs(w) + gamma(2) * glm::abs(hit.point);
    hit.normal = n;
    float phi = std::atan2(n.z, n.x);
    if (phi < 0.0f) phi += 2.0f * std::numbers::pi_v<float>;
    const float theta = std::acos(std::fmin(1.0f, std::fmax(-1.0f, n.y)));
    hit.uv = glm::vec2(phi * (0.5f * std::numbers::inv_pi_v<float>), theta * std::numbers::inv_pi_v<float>);
    return true;
}

}  // namespace collision

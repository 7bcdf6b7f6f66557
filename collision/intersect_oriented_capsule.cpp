// Ray-capsule of any orientation (segment a-b, radius r), §3.2's "segment-rotated capsule".
// The thesis rotates ray and capsule so the axis becomes Y by an angle about (0,1,0) x axis
// (collision/thesis/intersect_oriented_capsule.cpp: acos of a dot product, a special case when
// parallel, a quaternion matrix). Here the capsule's frame is an orthonormal basis around the
// unit axis u = (b - a) / |b - a| built by Duff et al. 2017 (detail::basis_around: no angle,
// no special case, continuous), the ray is expressed in it (a rotation: t is unchanged), and
// the Y-aligned capsule test runs there. The hit point and normal are then computed in world
// space from t: the point is re-projected from the closest point q of the segment a-b.
//
// Error bounds (eps = 2^-24, gamma(n) = n eps / (1 - n eps); m = (a + b) / 2, f = o - m,
// h_len = |b - a|, d_perp the part of d orthogonal to the axis):
//  t: as the Y-aligned capsule's, with the frame change added: expressing f and d in the
//     basis costs gamma(6) of |f| + |m| (m itself is rounded) and of |d|, and the basis is
//     orthonormal to gamma(6), which moves the axis by gamma(6) (h_len + r) at the ends. So
//       side: |t - t_exact| <= gamma(64) ((|f| + |m| + r + h_len)(1 + r / h) / |d_perp| + |t|),
//       ends: |t - t_exact| <= gamma(64) ((|f| + |m| + r + h_len)(1 + r / h) / |d| + |t|),
//     h the exact half-chord of the part crossed (the Y-aligned count, gamma(32), doubled).
//  point: q = a + s (b - a) is within gamma(3) (2 |a_i| + |b_i|) per axis of the exact
//     segment; then detail::reproject_on_sphere: point_error = gamma(7) |r n| + gamma(2) |point|
//     + gamma(3) (2 |a| + |b|) per axis.
// normal: normalize(point - q), outward.
// uv: not computed here (left 0): collision::surface_uv(shape, hit) gives it on request (surface_uv.hpp).
// Degenerate: radius <= 0 or non-finite, non-finite a, b, origin or direction, zero direction:
// false. a == b is a sphere.
#include <algorithm>
#include <cmath>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/detail/ray_quadric.hpp"

namespace collision {

bool intersect(const Ray& ray, const OrientedCapsule& c, RayHit& hit) {
    const float r = c.radius;
    if (!(r > 0.0f) || !std::isfinite(r)) return false;
    const glm::vec3 axis = c.b - c.a;
    const float len2 = glm::dot(axis, axis);
    if (!std::isfinite(len2) || !std::isfinite(c.a.x + c.a.y + c.a.z)) return false;
    if (len2 == 0.0f) return intersect(ray, Sphere{c.a, r}, hit);
    const float len = std::sqrt(len2);
    const glm::vec3 u = axis / len;
    glm::vec3 tu, tv;
    detail::basis_around(u, tu, tv);
    const glm::vec3 m = c.a + 0.5f * axis;
    const glm::vec3 f = ray.origin - m;
    const auto local = [&](const glm::vec3& v) { return glm::vec3(glm::dot(v, tu), glm::dot(v, u), glm::dot(v, tv)); };
    const Ray local_ray{local(f), local(ray.dir), ray.tmin, ray.tmax};
    RayHit local_hit;
    if (!intersect(local_ray, Capsule{glm::vec3(0.0f), r, len}, local_hit)) return false;

    const float t = local_hit.t;
    const glm::vec3 p = ray.at(t);
    const float s = std::clamp(glm::dot(p - c.a, axis) / len2, 0.0f, 1.0f);
    const glm::vec3 q = c.a + s * axis;
    glm::vec3 n, point, point_error;
    if (!detail::reproject_on_sphere(p, q, r, n, point, point_error)) return false;
    hit.t = t;
    hit.point = point;
    hit.point_error = point_error + gamma(3) * (2.0f * glm::abs(c.a) + glm::abs(c.b));
    hit.normal = n;
    hit.uv = glm::vec2(0.0f);
    return true;
}

}  // namespace collision

// Ray-ellipsoid (axis-aligned, semi-axes `radii`), §3.2: the thesis scales space about the
// centre by 1 / radii so the ellipsoid becomes the unit sphere (collision/thesis/ keeps its
// form). The same scaling is used here, with the robust sphere numerics: f' = (o - c) / radii,
// d' = d / radii; t is unchanged by the scaling; the stable roots of |f' + t d'| = 1
// (detail::stable_roots), the unit-sphere point re-projected (n' = normalize(f' + t d')),
// and back: point = c + radii * n', normal = normalize(n' / radii) (the inverse transpose of
// the scaling diag(radii) is diag(1 / radii)).
//
// Error bounds (eps = 2^-24, gamma(n) = n eps / (1 - n eps); primes: the scaled space):
//  t: |t - t_exact| <= gamma(40) ((|f'| + 1)(1 + 1 / h') / |d'| + |t|), h' the exact
//     half-chord of the unit sphere in scaled space: the sphere's gamma(32) plus the scaling's
//     rounding of f' and d' (one division each: relative eps per component).
//  point: n' is unit to gamma(6) (detail::reproject_on_sphere), radii * n' one more rounding,
//     + c one more: point_error = gamma(8) |radii * n'| + gamma(2) |point| per axis, a bound of
//     the distance to a point exactly on the ellipsoid along each axis. Along the surface the
//     point is as good as t up to max(radii) / min(radii): the re-projection is radial in
//     scaled space, not the nearest-point projection in world space.
// normal: normalize(n' / radii), outward.
// uv: not computed here (left 0): collision::surface_uv(shape, hit) gives it on request (surface_uv.hpp).
// Degenerate: any radius <= 0 or non-finite, non-finite centre/origin/direction, zero
// direction: false.
#include <cmath>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/detail/ray_quadric.hpp"

namespace collision {

bool intersect(const Ray& ray, const Ellipsoid& e, RayHit& hit) {
    const glm::vec3& radii = e.radii;
    if (!(radii.x > 0.0f && radii.y > 0.0f && radii.z > 0.0f)) return false;
    if (!std::isfinite(radii.x + radii.y + radii.z)) return false;
    const glm::vec3 f = (ray.origin - e.center) / radii;
    const glm::vec3 d = ray.dir / radii;
    float t0, t1, t;
    if (!detail::stable_roots(f, d, 1.0f, t0, t1)) return false;
    if (!detail::pick_root(t0, t1, ray, t)) return false;
    glm::vec3 n_unit, p_unit, unused;
    if (!detail::reproject_on_sphere(f + t * d, glm::vec3(0.0f), 1.0f, n_unit, p_unit, unused)) return false;
    const glm::vec3 w = radii * n_unit;
    const glm::vec3 n = n_unit / radii;
    const float n_len2 = glm::dot(n, n);
    if (!(n_len2 > 0.0f) || !std::isfinite(n_len2)) return false;
    hit.t = t;
    hit.point = e.center + w;
    hit.point_error = gamma(8) * glm::abs(w) + gamma(2) * glm::abs(hit.point);
    hit.normal = n / std::sqrt(n_len2);
    hit.uv = glm::vec2(0.0f);
    return true;
}

}  // namespace collision

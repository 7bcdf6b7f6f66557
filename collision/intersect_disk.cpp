// Ray-disk intersection: the plane crossing in double (collision/detail/ray_plane.hpp), then the
// radius test |x - centre|^2 <= r^2 in double on the double crossing point, so the inside
// decision is exact to ~1e-16 relative (the rim belongs to the disk).
// Bounds: |t - t_exact| <= eps |t| + 8 eps_d S / |n.d| (S as in detail/ray_plane.hpp); point within
// point_error of the plane per axis.
// normal: normalize(disk.normal) (two-sided, never flipped).
// uv: not computed here (left 0): collision::surface_uv(shape, hit) gives it on request (surface_uv.hpp).
// Degenerate: radius <= 0 or non-finite, zero or non-finite normal, non-finite ray, zero or
// parallel direction: false.
#include "collision/intersect.hpp"
#include "collision/detail/ray_plane.hpp"
#include "collision/detail/ray_quadric.hpp"

namespace collision {

bool intersect(const Ray& ray, const Disk& d, RayHit& hit) {
    if (!(d.radius > 0.0f) || !std::isfinite(d.radius)) return false;
    const float n_len2 = glm::dot(d.normal, d.normal);
    if (!(n_len2 > 0.0f) || !std::isfinite(n_len2)) return false;
    detail::PlaneCrossing x;
    if (!detail::ray_plane(ray, glm::dvec3(d.center), glm::dvec3(d.normal), x)) return false;
    const glm::dvec3 rel = x.point - glm::dvec3(d.center);
    const double rho2 = glm::dot(rel, rel);
    const double r = d.radius;
    if (!(rho2 <= r * r)) return false;
    const glm::vec3 n = d.normal / std::sqrt(n_len2);
    hit.t = x.t_float;
    hit.point = glm::vec3(x.point);
    hit.point_error = x.point_error;
    hit.normal = n;
    hit.uv = glm::vec2(0.0f);
    return true;
}

}  // namespace collision

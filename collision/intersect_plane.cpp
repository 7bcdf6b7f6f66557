// Ray-plane intersection (thesis §3.2 planes; §3.5 "floating point": a ray parallel to the plane
// is a defined miss, no division by zero reaches the result).
// Method and error bounds: collision/detail/ray_plane.hpp (the crossing in double):
//  |t - t_exact| <= eps |t| + 8 eps_d S / |n.d|, S = sum |n_i||p0_i - o_i| + |t| sum |n_i d_i|;
//  point within point_error of the plane per axis (gamma(2) |point| + the double's part).
// normal: normalize(plane.normal), the plane's own (two-sided, never flipped).
// uv: coordinates of the point in the plane, (point - plane.point) on the basis (t, b) of
//     detail::basis_around(normal).
// Degenerate: zero or non-finite normal, non-finite point/origin/direction, zero direction or a
// direction parallel to the plane: false.
#include "collision/intersect.hpp"
#include "collision/detail/ray_plane.hpp"
#include "collision/detail/ray_quadric.hpp"

namespace collision {

bool intersect(const Ray& ray, const Plane& p, RayHit& hit) {
    const float n_len2 = glm::dot(p.normal, p.normal);
    if (!(n_len2 > 0.0f) || !std::isfinite(n_len2)) return false;
    detail::PlaneCrossing x;
    if (!detail::ray_plane(ray, glm::dvec3(p.point), glm::dvec3(p.normal), x)) return false;
    const glm::vec3 n = p.normal / std::sqrt(n_len2);
    glm::vec3 tu, tv;
    detail::basis_around(n, tu, tv);
    const glm::vec3 rel(x.point - glm::dvec3(p.point));
    hit.t = x.t_float;
    hit.point = glm::vec3(x.point);
    hit.point_error = x.point_error;
    hit.normal = n;
    hit.uv = glm::vec2(glm::dot(rel, tu), glm::dot(rel, tv));
    return true;
}

}  // namespace collision

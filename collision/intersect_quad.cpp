// Ray-parallelogram (Quad) intersection: the plane of corner, normal edge_u x edge_v, crossed in
// double (collision/ray_plane.hpp; the normal's products of floats are exact in double), then
// the parallelogram coordinates of the crossing, also in double:
//   s = ((x - corner) x edge_v).n / n.n,  t = (edge_u x (x - corner)).n / n.n,
// inside when both are in [0, 1] (edges belong to the quad). The decision is exact to ~1e-15
// relative; two quads sharing an edge are not watertight in the Woop sense, but a ray can only
// slip between them within that 1e-15 band.
// Bounds: |t - t_exact| <= eps |t| + 8 eps_d S / |n.d| (S as in ray_plane.hpp); point within
// point_error of the plane per axis.
// normal: normalize(edge_u x edge_v) (two-sided, never flipped).  uv: (s, t).
// Degenerate: parallel or zero edges (n = 0), non-finite input, zero or parallel direction: false.
#include "collision/intersect.hpp"
#include "collision/ray_plane.hpp"

namespace collision {

bool intersect(const Ray& ray, const Quad& q, RayHit& hit) {
    const glm::dvec3 eu(q.edge_u), ev(q.edge_v), corner(q.corner);
    const glm::dvec3 n = glm::cross(eu, ev);
    const double nn = glm::dot(n, n);
    if (!(nn > 0.0) || !std::isfinite(nn)) return false;
    detail::PlaneCrossing x;
    if (!detail::ray_plane(ray, corner, n, x)) return false;
    const glm::dvec3 rel = x.point - corner;
    const double s = glm::dot(glm::cross(rel, ev), n) / nn;
    const double t = glm::dot(glm::cross(eu, rel), n) / nn;
    if (!(s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0)) return false;
    hit.t = x.t_float;
    hit.point = glm::vec3(x.point);
    hit.point_error = x.point_error;
    hit.normal = glm::vec3(n / std::sqrt(nn));
    hit.uv = glm::vec2(float(s), float(t));
    return true;
}

}  // namespace collision

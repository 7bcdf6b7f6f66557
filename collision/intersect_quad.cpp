// Ray-parallelogram (Quad) intersection, watertight.
//
// Hit or miss: the watertight test of collision/triangle_watertight.hpp (Woop, Benthin, Wald
// 2013) on the convex polygon of the four float vertices
//   v0 = corner, v1 = corner + edge_u, v2 = (corner + edge_u) + edge_v, v3 = corner + edge_v
// (each sum one float rounding, as a neighbouring face computes them): the vertices are
// translated, permuted and sheared into ray space, and the ray is inside when the four edge
// functions e_i = edge_function(v_i, v_i+1) have one sign (zeros allowed: edges and corners
// belong to the quad; a zero is re-decided in double, where its sign is exact). An edge shared
// with another quad or a triangle (collision/triangle_watertight.hpp, same edge_function) whose
// endpoints are bit-identical floats gives exactly the negated edge function there, so a ray
// through that edge is inside at least one of them: no leak through a closed mesh of quads and
// triangles, e.g. a cube of six Quads built from a box's lo corner and size vectors (every
// vertex coordinate is then lo_i or lo_i + size_i, whichever face computes it). Two quads whose
// shared corner rounds differently (e.g. corner + edge_v + edge_u in one of them) are not covered.
//
// The decision is exact for the sheared float vertices, so it differs from the exact
// parallelogram only where some exact edge function is within
//   de + 4 R (max|xt| + max|yt|) + 4 R^2
// of zero: de as in triangle_watertight.hpp (the shear's rounding) and R = gamma(2) max_i |v_i|
// (max norm, the exact vertices) the rounding of the vertex sums, moving each sheared coordinate
// by at most 2 R (|sx|, |sy| <= 1) and each edge function by 2 R |x| + 2 R |y| per endpoint.
//
// t and point: the plane of corner, normal edge_u x edge_v, crossed in double
// (collision/detail/ray_plane.hpp; the normal's products of floats are exact in double):
//   |t - t_exact| <= eps |t| + 8 eps_d S / |n.d|  (S as in detail/ray_plane.hpp; unchanged by the
//   watertight decision, which only selects whether there is a hit); point within point_error
// of the plane per axis. A ray nearly parallel to the plane (n.d == 0 in double) misses even
// when the sheared test says inside (the triangle test does the same for det == 0).
// normal: normalize(edge_u x edge_v) (two-sided, never flipped).
// uv: (s, t) of the double plane point, s = ((x - corner) x edge_v).n / n.n,
//   t = (edge_u x (x - corner)).n / n.n, clamped to [0, 1] (the decision is not made on them, so
//   they may stray ~1e-15 outside for hits on an edge); within ~1e-15 of exact, then one float
//   rounding.
// Degenerate: parallel or zero edges (n = 0), non-finite input or vertex sums, zero or
// non-finite direction: false.
#include <algorithm>

#include "collision/intersect.hpp"
#include "collision/detail/ray_plane.hpp"
#include "collision/triangle_watertight.hpp"

namespace collision {

bool intersect(const Ray& ray, const Quad& q, RayHit& hit) {
    const glm::dvec3 eu(q.edge_u), ev(q.edge_v), corner(q.corner);
    const glm::dvec3 n = glm::cross(eu, ev);
    const double nn = glm::dot(n, n);
    if (!(nn > 0.0) || !std::isfinite(nn)) return false;

    // t on the plane first: it rejects faces behind the ray or beyond tmax at the lowest cost;
    // the order does not change any answer.
    detail::PlaneCrossing x;
    if (!detail::ray_plane_t(ray, corner, n, x)) return false;

    const TriangleRay tr = prepare_triangle_ray(ray);
    if (!tr.valid) return false;
    const glm::vec3 v1 = q.corner + q.edge_u;
    const ShearedVertex s0 = shear_vertex(ray, tr, q.corner), s1 = shear_vertex(ray, tr, v1),
                        s2 = shear_vertex(ray, tr, v1 + q.edge_v), s3 = shear_vertex(ray, tr, q.corner + q.edge_v);
    float e0 = edge_function(s0, s1), e1 = edge_function(s1, s2), e2 = edge_function(s2, s3),
          e3 = edge_function(s3, s0);
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f || e3 == 0.0f) {
        e0 = edge_function_exact(s0, s1);
        e1 = edge_function_exact(s1, s2);
        e2 = edge_function_exact(s2, s3);
        e3 = edge_function_exact(s3, s0);
    }
    // Two-sided: all of one sign. All zero is a ray in the (projected) plane; a NaN or inf sum
    // (overflowing vertex sums) is rejected too.
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f || e3 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f || e3 > 0.0f))
        return false;
    const float sum = e0 + e1 + e2 + e3;
    if (sum == 0.0f || !std::isfinite(sum)) return false;

    if (!detail::ray_plane_point(ray, corner, n, x)) return false;
    const glm::dvec3 rel = x.point - corner;
    const double s = std::clamp(glm::dot(glm::cross(rel, ev), n) / nn, 0.0, 1.0);
    const double t = std::clamp(glm::dot(glm::cross(eu, rel), n) / nn, 0.0, 1.0);
    hit.t = x.t_float;
    hit.point = glm::vec3(x.point);
    hit.point_error = x.point_error;
    hit.normal = glm::vec3(n / std::sqrt(nn));
    hit.uv = glm::vec2(float(s), float(t));
    return true;
}

}  // namespace collision

// Thesis §3.2.5 segment-triangle as a ray cast: the triangle's plane (normal (b - a) x (c - a))
// by detail::segment_plane, rejected when n.d is exactly 0 (a segment lying in the plane is
// ignored, as the thesis admits), then the point o + t d tested by Ericson's barycentric
// coordinates (§2.4: d00 = v0.v0, d01 = v0.v1, d11 = v1.v1, d20 = v2.v0, d21 = v2.v1,
// denom = d00 d11 - d01^2, v = (d11 d20 - d01 d21) / denom, w = (d00 d21 - d01 d20) / denom,
// u = 1 - v - w), inside when all three are in [0, 1].
// Weaknesses kept: the barycentrics are computed from the rounded point, independently for
// each triangle, so a ray through an edge shared by two triangles can be outside both (the
// leak the watertight test removes); denom cancels for slivers (0 or negative: the division
// gives inf/NaN coordinates, which fail the inside test: no hit). Normal normalize(n); uv
// (v, w), the weights of b and c; point o + t d; point_error 0. NaN input: no hit.
#include "collision/thesis/detail/barycentric.hpp"
#include "collision/thesis/intersect.hpp"
#include "collision/thesis/detail/textbook.hpp"

namespace collision::thesis {

bool intersect(const Ray& ray, const Triangle& tri, RayHit& hit) {
    const glm::vec3 n = glm::cross(tri.b - tri.a, tri.c - tri.a);
    float t;
    if (!detail::segment_plane(ray, tri.a, n, t)) return false;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    const glm::vec3 p = ray.at(t);
    const Barycentric bary = barycentric(tri, p);
    if (!bary.inside()) return false;
    hit.t = t;
    hit.point = p;
    hit.point_error = glm::vec3(0.0f);
    hit.normal = glm::normalize(n);
    hit.uv = glm::vec2(bary.v, bary.w);
    return true;
}

}  // namespace collision::thesis

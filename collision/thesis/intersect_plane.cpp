// Thesis §3.2.5 segment-plane as a ray cast, and the cylinder's cap test (§3.1.4) on its own as
// the disk: t = n.(p - o) / n.d, rejected when n.d is exactly 0 (a segment in the plane is
// ignored, as the thesis admits; a nearly parallel one divides by a tiny number, the §3.5.1
// problem, and gets a huge t); disk: the point o + t d closer than r to the centre (strictly).
// Normal: the shape's normal as given; point o + t d, point_error 0; uv as the robust versions.
// Degenerate input: a zero normal makes n.d = 0: no hit; NaN input: no hit.
#include "collision/detail/ray_quadric.hpp"
#include "collision/thesis/intersect.hpp"
#include "collision/thesis/detail/textbook.hpp"

namespace collision::thesis {

namespace {

bool plane_hit(const Ray& ray, const glm::vec3& point, const glm::vec3& normal, RayHit& hit) {
    float t;
    if (!detail::segment_plane(ray, point, normal, t)) return false;
    if (!(t > ray.tmin && t < ray.tmax)) return false;
    hit.t = t;
    hit.point = ray.at(t);
    hit.point_error = glm::vec3(0.0f);
    hit.normal = normal;
    return true;
}

}  // namespace

bool intersect(const Ray& ray, const Plane& p, RayHit& hit) {
    RayHit h;
    if (!plane_hit(ray, p.point, p.normal, h)) return false;
    glm::vec3 tu, tv;
    collision::detail::basis_around(p.normal, tu, tv);
    h.uv = glm::vec2(glm::dot(h.point - p.point, tu), glm::dot(h.point - p.point, tv));
    hit = h;
    return true;
}

bool intersect(const Ray& ray, const Disk& d, RayHit& hit) {
    RayHit h;
    if (!plane_hit(ray, d.center, d.normal, h)) return false;
    const glm::vec3 rel = h.point - d.center;
    const float rho = glm::length(rel);
    if (!(rho < d.radius)) return false;
    glm::vec3 tu, tv;
    collision::detail::basis_around(d.normal, tu, tv);
    h.uv = glm::vec2(rho / d.radius, collision::detail::turn_fraction(glm::dot(rel, tv), glm::dot(rel, tu)));
    hit = h;
    return true;
}

}  // namespace collision::thesis

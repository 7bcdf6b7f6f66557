#include "collision/surface_uv.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "collision/detail/ray_quadric.hpp"

namespace collision {

glm::vec2 surface_uv(const Sphere&, const RayHit& hit) { return detail::sphere_uv(hit.normal); }

glm::vec2 surface_uv(const Ellipsoid& e, const RayHit& hit) {
    return detail::sphere_uv(glm::normalize((hit.point - e.center) / e.radii));
}

glm::vec2 surface_uv(const Cylinder& c, const RayHit& hit) {
    const float r = c.radius;
    if (hit.normal.y != 0.0f)
        return {(hit.point.x - c.center.x) / (2.0f * r) + 0.5f, (hit.point.z - c.center.z) / (2.0f * r) + 0.5f};
    const float ylo = c.center.y - 0.5f * c.height;
    return {detail::turn_fraction(hit.normal.z, hit.normal.x), (hit.point.y - ylo) / c.height};
}

glm::vec2 surface_uv(const Capsule& c, const RayHit& hit) {
    const float r = c.radius;
    const float ylo = c.center.y - 0.5f * c.height;
    return {detail::turn_fraction(hit.normal.z, hit.normal.x), (hit.point.y - (ylo - r)) / (c.height + 2.0f * r)};
}

glm::vec2 surface_uv(const OrientedCapsule& c, const RayHit& hit) {
    const glm::vec3 axis = c.b - c.a;
    const float len2 = glm::dot(axis, axis);
    if (len2 == 0.0f) return surface_uv(Sphere{c.a, c.radius}, hit);
    const float len = std::sqrt(len2);
    const glm::vec3 u = axis / len;
    glm::vec3 tu, tv;
    detail::basis_around(u, tu, tv);
    return {detail::turn_fraction(glm::dot(hit.normal, tv), glm::dot(hit.normal, tu)),
            (glm::dot(hit.point - c.a, u) + c.radius) / (len + 2.0f * c.radius)};
}

glm::vec2 surface_uv(const Disk& d, const RayHit& hit) {
    const glm::vec3 n = glm::normalize(d.normal);
    glm::vec3 tu, tv;
    detail::basis_around(n, tu, tv);
    const glm::vec3 rel = hit.point - d.center;
    return {glm::length(rel) / d.radius, detail::turn_fraction(glm::dot(rel, tv), glm::dot(rel, tu))};
}

}  // namespace collision

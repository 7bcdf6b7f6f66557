// Thesis §3.2.5 (segment against a rotated capsule, used for the triangle's edges): rotate the
// segment into a frame where the capsule stands upright on Y, run the Y-aligned thesis test,
// rotate the result back. The rotation is the thesis's "suboptimal" Euler-angle way:
//   alpha = glm::angle((0,1,0), normalize(b - a))            (acos of a clamped dot product)
//   axis  = (0,1,0) x (b - a), or (1,0,0) when alpha is exactly 0 or pi,
// a quaternion about `axis` by -alpha turned into a 4x4 matrix (§2.6) applied to the ray's
// origin (relative to the capsule's midpoint) and direction; the hit point and normal are
// rotated back by +alpha.
// Weaknesses kept: acos is ill-conditioned near 0 and pi (an axis 1e-4 rad off Y gets an angle
// off by ~1e-4 of itself... and worse), and the cross product that gives the rotation axis
// shrinks to rounding noise as b - a approaches -Y, so nearly vertical capsules are rotated by
// a wrong angle about a wrong axis; the Y-aligned thesis test's own weaknesses come along.
// point_error 0. Degenerate input: a == b normalizes a zero vector (NaN angle): no hit.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include "collision/thesis/intersect.hpp"

namespace collision::thesis {

bool intersect(const Ray& ray, const OrientedCapsule& c, RayHit& hit) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 axis_vec = c.b - c.a;
    const float length = glm::length(axis_vec);
    // glm::angle (gtx/vector_angle): acos of the dot product clamped to [-1, 1].
    const float alpha = std::acos(std::clamp(glm::dot(up, glm::normalize(axis_vec)), -1.0f, 1.0f));
    glm::vec3 rot_axis(1.0f, 0.0f, 0.0f);
    if (!(alpha == 0.0f || alpha == glm::pi<float>())) rot_axis = glm::normalize(glm::cross(up, axis_vec));
    const glm::mat4 to_local = glm::mat4_cast(glm::angleAxis(-alpha, rot_axis));
    const glm::mat4 to_world = glm::mat4_cast(glm::angleAxis(alpha, rot_axis));
    const glm::vec3 mid = 0.5f * (c.a + c.b);
    const Ray local{glm::vec3(to_local * glm::vec4(ray.origin - mid, 1.0f)), glm::vec3(to_local * glm::vec4(ray.dir, 0.0f)),
                    ray.tmin, ray.tmax};
    RayHit local_hit;
    if (!intersect(local, Capsule{glm::vec3(0.0f), c.radius, length}, local_hit)) return false;
    hit = local_hit;
    hit.point = glm::vec3(to_world * glm::vec4(local_hit.point, 1.0f)) + mid;
    hit.normal = glm::vec3(to_world * glm::vec4(local_hit.normal, 0.0f));
    hit.point_error = glm::vec3(0.0f);
    return true;
}

}  // namespace collision::thesis

// Leaving a surface without re-hitting it: pbrt-v4's OffsetRayOrigin (§6.8.6). The exact
// surface point lies in the box hit.point +- point_error. Pushing the origin along the normal by
// d = dot(|n|, point_error) (the box's extent along n) puts it outside the slab of planes
// through that box, on the side `dir` goes to; rounding each coordinate one float further away
// keeps the rounded sum from landing back inside.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"
#include "raytracer/geometry/surface_hit.hpp"

namespace sweeptrace {
namespace {

glm::vec3 offset_origin(const glm::vec3& p, const glm::vec3& error, const glm::vec3& n, const glm::vec3& dir) {
    const float d = glm::dot(glm::abs(n), error);
    glm::vec3 offset = d * n;
    if (glm::dot(dir, n) < 0.0f) offset = -offset;
    glm::vec3 po = p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) po[i] = collision::next_float_up(po[i]);
        else if (offset[i] < 0.0f) po[i] = collision::next_float_down(po[i]);
    }
    return po;
}

}  // namespace

collision::Ray spawn_ray(const SurfaceHit& hit, const glm::vec3& dir) {
    return collision::Ray{offset_origin(hit.point, hit.point_error, hit.normal, dir), dir, 0.0f,
                          std::numeric_limits<float>::infinity()};
}

// The ray runs from the offset origin o to the target with dir = target - o, so t = 1 is the
// target, and it must stop short of the target's own surface while still seeing every blocker
// before it. Two things blur where that surface is met along the ray:
//  - the target point is only known within target +- target_error; along dir that box spans
//    parameters 1 +- s, s = dot(target_error, |dir|) / |dir|^2 (its support along dir over the
//    ray's length); a hit reported on the same surface carries a box of the same kind: 2 s;
//  - the intersector's own t error at the far end, which for curved shapes is larger than the
//    point error (the point is re-projected, t is not). The largest of collision/'s stated
//    bounds is the sphere's, gamma(32) ((|f| + r)(1 + r / h) / |d| + |t|) at t = 1 with
//    f = o - centre. For an origin outside the sphere's radius of the target (r <= |d|),
//    |f| <= |d| + r <= 2 |d|, and a target facing the ray within 60 degrees (h >= r / 2):
//    gamma(32) (3 * 3 + 1) = 10 gamma(32), about 2e-5.
// Plus gamma(3) for forming dir = target - o and o + t dir. So
//   tmax = 1 - 2 s - 10 gamma(32) - gamma(3).
// Not covered: targets seen at grazing angles beyond 60 degrees on strongly curved lights,
// where a false "occluded" is possible (such samples carry a small cosine weight), and a
// blocker within that last fraction of the segment of the target (it would touch the light).
collision::Ray spawn_ray_to(const SurfaceHit& hit, const glm::vec3& target, const glm::vec3& target_error) {
    const glm::vec3 o = offset_origin(hit.point, hit.point_error, hit.normal, target - hit.point);
    const glm::vec3 dir = target - o;
    const float len2 = glm::dot(dir, dir);
    float s = len2 > 0.0f ? glm::dot(target_error, glm::abs(dir)) / len2 : 0.0f;
    if (!std::isfinite(s)) s = 0.0f;
    const float tmax = std::max(0.0f, 1.0f - 2.0f * s - 10.0f * collision::gamma(32) - collision::gamma(3));
    return collision::Ray{o, dir, 0.0f, tmax};
}

}  // namespace sweeptrace

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

// pbrt-v4's SpawnRayTo(Interaction, Interaction): both ends leave their surfaces. The origin o is
// pushed off the hit toward the target, the target off its own surface toward o, each by its
// error bound, so the target's surface (its exact point lies in the target's error box) is met,
// if at all, only beyond the offset end pt: for a chord of a convex light both o and pt lie
// inside it and the exact crossing is at t >= 1; for a light seen from outside pt lies in front
// of the tangent slab. With dir = pt - o (t = 1 is pt) the only way to report the target's own
// surface before t = 1 is the intersector's t error, and the largest of collision/'s stated
// bounds is the sphere's: gamma(32) ((|f| + r)(1 + r / h) / |d| + |t|), f = o - centre. At the
// crossing t ~ 1 the half-chord is h = r cos_t (cos_t the cosine between the ray and the
// light's normal there, which `target_normal` gives), and |f| <= |dir| + r, so with
// k = r / |dir| the bound is gamma(32) ((1 + 2 k)(1 + 1 / cos_t) + 1). Two placements bound k:
// the origin on the same sphere (a chord, |dir| = 2 r cos_t: k = 1 / (2 cos_t)) and an origin
// at least r away from the light (k <= 1); k = max(1, 1 / (2 cos_t)) covers both. Forming dir
// and o + t dir rounds the end by gamma(3) |dir| per axis, which moves the crossing by at most
// gamma(3) sqrt(3) / cos_t in t. So
//   tmax = 1 - gamma(32) ((1 + 2 k)(1 + 1 / cos_t) + 1) - 2 gamma(3) / cos_t.
// The margin grows like 1 / cos_t^2 at grazing angles (the real conditioning of a tangent hit:
// no float method places such a crossing better); a blocker within that last fraction of the
// segment touches the light anyway. Not covered: an origin closer to a strongly curved light
// than its radius, seeing it at grazing angles (k above the bound; a false "occluded" is then
// possible, weighted by a small cosine).
collision::Ray spawn_ray_to(const SurfaceHit& hit, const glm::vec3& target, const glm::vec3& target_error,
                            const glm::vec3& target_normal) {
    const glm::vec3 o = offset_origin(hit.point, hit.point_error, hit.normal, target - hit.point);
    const glm::vec3 pt = offset_origin(target, target_error, target_normal, o - target);
    const glm::vec3 dir = pt - o;
    const float len = glm::length(dir);
    const float cos_t = len > 0.0f ? std::abs(glm::dot(target_normal, dir)) / len : 0.0f;
    float tmax = 0.0f;  // a tangent or degenerate segment: nothing can be decided, nothing blocks
    if (cos_t > 0.0f && std::isfinite(cos_t)) {
        const float inv_cos = 1.0f / cos_t;
        const float k = std::max(1.0f, 0.5f * inv_cos);
        const float margin = collision::gamma(32) * ((1.0f + 2.0f * k) * (1.0f + inv_cos) + 1.0f) +
                             2.0f * collision::gamma(3) * inv_cos;
        tmax = std::max(0.0f, 1.0f - margin);
    }
    return collision::Ray{o, dir, 0.0f, tmax};
}

}  // namespace sweeptrace

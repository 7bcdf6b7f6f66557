// Ray-capsule (Y-aligned "bean" of §3.1: a cylinder side closed by two hemispheres).
// The thesis runs its sphere and cylinder tests and keeps the nearest hit
// (collision/thesis/intersect_capsule.cpp). Here the capsule is treated as the convex set it
// is: the infinite cylinder of radius r around the axis bounds it, so the ray first meets the
// infinite cylinder (stable 2D quadratic); if that entry lies between the end points' heights
// it is the capsule's entry, otherwise the capsule's entry is on the end sphere on that side
// (the ray is inside the infinite cylinder when it crosses the end's height, hence inside that
// sphere), or there is none. The exit is found the same way. A ray parallel to the axis enters
// through one end sphere and leaves through the other. A ray starting inside hits the far side.
//
// Error bounds (eps = 2^-24, gamma(n) = n eps / (1 - n eps); f = o - centre):
//  side:  |t - t_exact| <= gamma(32) ((|f_xz| + r)(1 + r / h) / |d_xz| + |t|), h the exact 2D
//         half-chord (the sphere's analysis in 2D);
//  ends:  |t - t_exact| <= gamma(32) ((|o - e| + r + |e|)(1 + r / h) / |d| + |t|), e the end
//         point (centre +- height/2 along y, one rounding: a shift of eps |e| of the sphere,
//         which moves t by at most that times r / (h |d|)), h the sphere's exact half-chord.
//  point: re-projected from the closest axis point q (y clamped to the ends):
//         point = q + r normalize(p - q), gamma(7) |r n| + gamma(2) |point| per axis
//         (detail::reproject_on_sphere; q's rounding eps |q_i| <= eps (|point_i| + |r n_i|)).
// normal: normalize(point - q), outward.
// uv: not computed here (left 0): collision::surface_uv(shape, hit) gives it on request (surface_uv.hpp).
// Degenerate: radius <= 0 or non-finite, height < 0 or non-finite (height 0 is a sphere),
// non-finite centre/origin/direction, zero direction: false.
#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/detail/ray_quadric.hpp"

namespace collision {

namespace {

// t of the capsule's entry (end = 0) or exit (end = 1); false if the line misses it.
bool capsule_end(const glm::vec3& f, const glm::vec3& d, float r, float ylo, float yhi, bool parallel, float side_t,
                 int end, float& t) {
    bool bottom;
    if (parallel) {
        bottom = (end == 0) == (d.y > 0.0f);  // entering upward: through the bottom sphere
    } else {
        const float y = f.y + side_t * d.y;
        if (y >= ylo && y <= yhi) {
            t = side_t;
            return true;
        }
        bottom = y < ylo;
    }
    const glm::vec3 fe(f.x, f.y - (bottom ? ylo : yhi), f.z);
    float t0, t1;
    if (!detail::stable_roots(fe, d, r, t0, t1)) return false;
    t = end == 0 ? t0 : t1;
    return true;
}

}  // namespace

bool intersect(const Ray& ray, const Capsule& cap, RayHit& hit) {
    const float r = cap.radius;
    if (!(r > 0.0f) || !std::isfinite(r) || !(cap.height >= 0.0f) || !std::isfinite(cap.height)) return false;
    // Work relative to the centre: ends at y = -+height/2 (exact), f = o - centre.
    const glm::vec3 f = ray.origin - cap.center;
    const glm::vec3& d = ray.dir;
    if (!std::isfinite(f.x + f.y + f.z) || !std::isfinite(d.x + d.y + d.z)) return false;
    const glm::vec2 f2(f.x, f.z), d2(d.x, d.z);
    const bool parallel = d2 == glm::vec2(0.0f);
    float side0 = 0.0f, side1 = 0.0f;
    if (parallel) {
        if (d.y == 0.0f || !(glm::dot(f2, f2) <= r * r)) return false;
    } else if (!detail::stable_roots(f2, d2, r, side0, side1)) {
        return false;
    }
    const float half = 0.5f * cap.height;
    float t_enter, t_exit;
    if (!capsule_end(f, d, r, -half, half, parallel, side0, 0, t_enter)) return false;
    if (!capsule_end(f, d, r, -half, half, parallel, side1, 1, t_exit)) return false;
    float t;
    if (!detail::pick_root(t_enter, t_exit, ray, t)) return false;

    const glm::vec3 p = ray.at(t);
    const float ylo = cap.center.y - half, yhi = cap.center.y + half;
    const glm::vec3 q(cap.center.x, std::clamp(p.y, ylo, yhi), cap.center.z);
    glm::vec3 n, point, point_error;
    if (!detail::reproject_on_sphere(p, q, r, n, point, point_error)) return false;
    hit.t = t;
    hit.point = point;
    hit.point_error = point_error;
    hit.normal = n;
    hit.uv = glm::vec2(0.0f);
    return true;
}

}  // namespace collision

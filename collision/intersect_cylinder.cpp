// Ray-cylinder (Y-aligned, closed by two flat caps), thesis §3.1 "cylinder-cylinder,
// continuous" as a ray cast. The thesis intersects the two cap planes and the side separately
// (collision/thesis/intersect_cylinder.cpp); here the solid cylinder is the intersection of
// the infinite cylinder (x - cx)^2 + (z - cz)^2 <= r^2 and the slab ylo <= y <= yhi, so the
// ray's part of it is the intersection of two t intervals, like the box's slab test:
//  - side interval: the stable 2D quadratic of detail::stable_roots on (x, z); a ray parallel
//    to the axis (d.x = d.z = 0) is inside for all t or for none, decided by its distance;
//  - cap interval: ((ylo - o.y) / d.y, (yhi - o.y) / d.y); d.y = 0 is all t or none.
// Entry = max of the two starts, exit = min of the two ends; the binding one gives the normal
// (ties, i.e. the rim, go to the cap). A ray starting inside hits the far side.
//
// Error bounds (eps = 2^-24, gamma(n) = n eps / (1 - n eps); f = o - centre; in 2D (x, z)):
//  side: |t - t_exact| <= gamma(32) ((|f_xz| + r)(1 + r / h) / |d_xz| + |t|), h the exact 2D
//        half-chord sqrt(r^2 - l_xz^2); the sphere's analysis (intersect_sphere.cpp) in 2D.
//  caps: |t - t_exact| <= gamma(3) (|t| + |y_cap| / |d.y|): y_cap = c.y +- h/2 costs one
//        rounding, the subtraction and division two more.
//  point: re-projected on the computed surface: side hits onto the circle (gamma(7) |r n| +
//        gamma(2) |point| per axis, as detail::reproject_on_sphere) with y clamped to the caps;
//        cap hits get y = the cap exactly and (x, z) pulled inside the rim. The same per-axis
//        bound is stored for both.
// normal: side (n.x, 0, n.z), caps (0, +-1, 0).
// uv: not computed here (left 0): collision::surface_uv(shape, hit) gives it on request (surface_uv.hpp).
// Degenerate: radius or height <= 0 or non-finite, non-finite centre/origin/direction, zero
// direction: false.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec2.hpp>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/detail/ray_quadric.hpp"

namespace collision {

bool intersect(const Ray& ray, const Cylinder& cyl, RayHit& hit) {
    const float r = cyl.radius;
    if (!(r > 0.0f) || !std::isfinite(r) || !(cyl.height > 0.0f) || !std::isfinite(cyl.height)) return false;
    constexpr float inf = std::numeric_limits<float>::infinity();
    const glm::vec3 f = ray.origin - cyl.center;
    const glm::vec3& d = ray.dir;
    if (!std::isfinite(f.x + f.y + f.z) || !std::isfinite(d.x + d.y + d.z)) return false;
    const glm::vec2 f2(f.x, f.z), d2(d.x, d.z);

    float side0 = -inf, side1 = inf;
    if (d2 == glm::vec2(0.0f)) {
        if (d.y == 0.0f || !(glm::dot(f2, f2) <= r * r)) return false;
    } else if (!detail::stable_roots(f2, d2, r, side0, side1)) {
        return false;
    }
    const float ylo = cyl.center.y - 0.5f * cyl.height, yhi = cyl.center.y + 0.5f * cyl.height;
    float cap0 = -inf, cap1 = inf;
    if (d.y != 0.0f) {
        cap0 = (ylo - ray.origin.y) / d.y;
        cap1 = (yhi - ray.origin.y) / d.y;
        if (cap0 > cap1) std::swap(cap0, cap1);
    } else if (ray.origin.y < ylo || ray.origin.y > yhi) {
        return false;
    }
    const bool enter_cap = cap0 >= side0, exit_cap = cap1 <= side1;
    const float t_enter = enter_cap ? cap0 : side0, t_exit = exit_cap ? cap1 : side1;
    if (!(t_enter <= t_exit)) return false;
    float t;
    bool on_cap, entering;
    if (t_enter > ray.tmin && t_enter < ray.tmax) {
        t = t_enter, on_cap = enter_cap, entering = true;
    } else if (t_exit > ray.tmin && t_exit < ray.tmax) {
        t = t_exit, on_cap = exit_cap, entering = false;
    } else {
        return false;
    }

    const glm::vec3 p = ray.at(t);
    glm::vec3 n, point, point_error;
    if (on_cap) {
        // Entering through a cap means moving toward the slab: the cap faced is the one the
        // ray comes from; leaving, the one it goes to.
        const bool top = entering == (d.y < 0.0f);
        n = glm::vec3(0.0f, top ? 1.0f : -1.0f, 0.0f);
        glm::vec2 rel(p.x - cyl.center.x, p.z - cyl.center.z);
        const float rho2 = glm::dot(rel, rel);
        if (rho2 > r * r) rel *= r / std::sqrt(rho2);
        point = glm::vec3(cyl.center.x + rel.x, top ? yhi : ylo, cyl.center.z + rel.y);
        point_error = gamma(7) * glm::vec3(std::fabs(rel.x), 0.0f, std::fabs(rel.y)) + gamma(2) * glm::abs(point);
    } else {
        // p - q has y = 0 exactly, so this re-projects onto the circle at height p.y.
        const glm::vec3 q(cyl.center.x, p.y, cyl.center.z);
        if (!detail::reproject_on_sphere(p, q, r, n, point, point_error)) return false;
        point.y = std::clamp(p.y, ylo, yhi);
        point_error.y = gamma(2) * std::fabs(point.y);
    }
    hit.t = t;
    hit.point = point;
    hit.point_error = point_error;
    hit.normal = n;
    hit.uv = glm::vec2(0.0f);
    return true;
}

}  // namespace collision

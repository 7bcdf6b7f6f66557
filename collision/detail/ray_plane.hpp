#pragma once
// Shared numerics of the flat ray tests (plane, disk, quad): the line against a plane in double.
//
// Why double: the float formula t = n.(p0 - o) / n.d cancels in the numerator when the origin is
// near the plane and loses the plane's position for far origins; the flat shapes also need the
// crossing point to decide inside/outside (disk radius, quad edges). In double the inputs are
// floats, so p0 - o and the products are exact or within 2^-53, and the crossing is known to
// ~1e-16 relative, far below float resolution; double costs the same as float in scalar code.
//
// Bounds (eps = 2^-24, eps_d = 2^-53, S = sum_i |n_i| (|p0_i - o_i|) + |t| sum_i |n_i d_i|):
//  t (double): |t_d - t_exact| <= 8 eps_d S / |n.d| (the dot products' gamma_d(4) each, first
//     order); the float t adds one rounding: |t - t_exact| <= eps |t| + 8 eps_d S / |n.d|.
//  point: float(o + t_d d) lies within gamma(2) |point_i| per axis of the double point, which is
//     within 8 eps_d S / |n| of the plane (distance); point_error is the sum, per axis.
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "collision/finite.hpp"
#include "collision/float_error.hpp"
#include "collision/ray.hpp"

namespace collision::detail {

struct PlaneCrossing {
    double t = 0.0;
    float t_float = 0.0f;
    glm::dvec3 point{0.0};
    glm::vec3 point_error{0.0f};
};

// The line o + t d against n.(x - p0) = 0 with n given in double (need not be unit): t only,
// without the point (for tests that reject most candidates on t before doing more work). False
// for a line parallel to the plane (n.d == 0: also a line lying in it, which touches the plane
// everywhere and has no first crossing), non-finite input, or t outside (tmin, tmax).
inline bool ray_plane_t(const Ray& ray, const glm::dvec3& p0, const glm::dvec3& n, PlaneCrossing& out) {
    const glm::dvec3 o(ray.origin), d(ray.dir);
    const double denom = glm::dot(n, d);
    if (denom == 0.0 || !std::isfinite(denom)) return false;
    const double t = glm::dot(n, p0 - o) / denom;
    if (!std::isfinite(t)) return false;
    const float tf = float(t);
    if (!(tf > ray.tmin) || !(tf < ray.tmax)) return false;
    out.t = t;
    out.t_float = tf;
    return true;
}

// Completes a crossing found by ray_plane_t: the point and its error. False if the point
// overflows.
inline bool ray_plane_point(const Ray& ray, const glm::dvec3& p0, const glm::dvec3& n, PlaneCrossing& out) {
    const glm::dvec3 o(ray.origin), d(ray.dir);
    const double t = out.t;
    out.point = o + t * d;
    if (!finite(out.point)) return false;
    const glm::dvec3 an = glm::abs(n);
    const double s = glm::dot(an, glm::abs(p0 - o)) + std::fabs(t) * glm::dot(an, glm::abs(d));
    const double n_len = glm::length(n);
    const double plane_distance = 8.0 * 0x1p-53 * s / n_len;
    // Distance along the unit normal spread per axis (|n_i| / |n|), plus the float rounding.
    out.point_error = glm::vec3(gamma(2) * glm::abs(glm::vec3(out.point)) + glm::vec3(plane_distance * an / n_len));
    return true;
}

// Both steps: t, point and point_error.
inline bool ray_plane(const Ray& ray, const glm::dvec3& p0, const glm::dvec3& n, PlaneCrossing& out) {
    return ray_plane_t(ray, p0, n, out) && ray_plane_point(ray, p0, n, out);
}

}  // namespace collision::detail

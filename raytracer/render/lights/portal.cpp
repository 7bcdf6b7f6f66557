#include "raytracer/render/lights/portal.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace sweeptrace {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}  // namespace

// The rectangle seen from p, in Urena et al.'s local frame: origin p, axes ex, ey and z (the
// normal turned so that the rectangle lies at z = z0 < 0), the rectangle [x0, x1] x [y0, y1] in
// that plane; b0, b1, k and the solid angle S as the paper's sampling needs them. In double: S is
// a sum of four angles minus 2 pi, which cancels for a small or far window (a solid angle of
// 1e-4 sr keeps 12 digits in double, 4 in float), and sample() and pdf() must both get the same S.
struct Portal::View {
    double x0 = 0.0, y0 = 0.0, z0 = 0.0, x1 = 0.0, y1 = 0.0;
    double b0 = 0.0, b1 = 0.0, k = 0.0, s = 0.0;
    glm::dvec3 z{0.0};
};

Portal::Portal(const std::array<glm::vec3, 4>& corners) {
    corner_ = glm::dvec3(corners[0]);
    const glm::dvec3 e1 = glm::dvec3(corners[1]) - corner_, e3 = glm::dvec3(corners[3]) - corner_;
    width_ = glm::length(e1);
    height_ = glm::length(e3);
    ex_ = e1 / width_;
    ey_ = e3 / height_;
    ez_ = glm::normalize(glm::cross(ex_, ey_));
}

bool Portal::view_from(const glm::vec3& p, View& v) const {
    const glm::dvec3 d = corner_ - glm::dvec3(p);
    v.x0 = glm::dot(d, ex_);
    v.y0 = glm::dot(d, ey_);
    v.z0 = glm::dot(d, ez_);
    v.z = ez_;
    if (v.z0 > 0.0) {
        v.z0 = -v.z0;
        v.z = -v.z;
    }
    if (!(v.z0 < 0.0)) return false;  // in the plane (or NaN): no solid angle
    v.x1 = v.x0 + width_;
    v.y1 = v.y0 + height_;
    // The normals of the four planes through p and an edge, and the angles between them.
    const glm::dvec3 n0 = glm::normalize(glm::dvec3(0.0, v.z0, -v.y0));
    const glm::dvec3 n1 = glm::normalize(glm::dvec3(-v.z0, 0.0, v.x1));
    const glm::dvec3 n2 = glm::normalize(glm::dvec3(0.0, -v.z0, v.y1));
    const glm::dvec3 n3 = glm::normalize(glm::dvec3(v.z0, 0.0, -v.x0));
    const auto angle = [](const glm::dvec3& a, const glm::dvec3& b) { return std::acos(std::clamp(-glm::dot(a, b), -1.0, 1.0)); };
    const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
    v.b0 = n0.z;
    v.b1 = n2.z;
    v.k = kTwoPi - g2 - g3;
    v.s = g0 + g1 - v.k;
    return v.s > 0.0 && std::isfinite(v.s);
}

double Portal::solid_angle(const glm::vec3& p) const {
    View v;
    return view_from(p, v) ? v.s : 0.0;
}

bool Portal::sample(const glm::vec3& p, float u1, float u2, glm::vec3& dir, float& pdf) const {
    View v;
    if (!view_from(p, v)) return false;
    // x: the area of the spherical rectangle to the left of x is u1 S (the paper's eq. 6 to 9).
    const double au = u1 * v.s + v.k;
    const double fu = (std::cos(au) * v.b0 - v.b1) / std::sin(au);
    const double cu = std::clamp(std::copysign(1.0, fu) / std::sqrt(fu * fu + v.b0 * v.b0), -1.0, 1.0);
    // cu = +-1 (an edge) gives an infinite quotient, which the clamp puts on that edge.
    const double xu = std::clamp(-(cu * v.z0) / std::sqrt(1.0 - cu * cu), v.x0, v.x1);
    // y: uniform in the height of the arc's projection onto the y axis (eq. 10 to 12).
    const double dd = std::sqrt(xu * xu + v.z0 * v.z0);
    const double h0 = v.y0 / std::sqrt(dd * dd + v.y0 * v.y0), h1 = v.y1 / std::sqrt(dd * dd + v.y1 * v.y1);
    const double hv = h0 + u2 * (h1 - h0), hv2 = hv * hv;
    const double yv = hv2 < 1.0 ? std::clamp(hv * dd / std::sqrt(1.0 - hv2), v.y0, v.y1) : v.y1;
    const glm::dvec3 w = xu * ex_ + yv * ey_ + v.z0 * v.z;
    dir = glm::vec3(glm::normalize(w));
    pdf = static_cast<float>(1.0 / v.s);
    return std::isfinite(pdf) && pdf > 0.0f;
}

float Portal::pdf(const glm::vec3& p, const glm::vec3& dir) const {
    View v;
    if (!view_from(p, v)) return 0.0f;
    const glm::dvec3 d(dir);
    const double dz = glm::dot(d, v.z);
    if (!(dz < 0.0)) return 0.0f;  // away from the rectangle's plane
    const double t = v.z0 / dz;
    const double x = t * glm::dot(d, ex_), y = t * glm::dot(d, ey_);
    if (!(x >= v.x0 && x <= v.x1 && y >= v.y0 && y <= v.y1)) return 0.0f;
    return static_cast<float>(1.0 / v.s);
}

}  // namespace sweeptrace

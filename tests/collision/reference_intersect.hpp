#pragma once
// Long double reference ray-shape intersectors, for tests and accuracy tools.
//
// Self-contained: GLM only, nothing of collision/ (shapes are passed as long double vectors
// and scalars), so tools can include it next to any float implementation they measure.
// x86-64 long double has a 64-bit mantissa (eps = 2^-64): products of two floats are exact
// and every rounding here is ~1e-11 of a float's, so on the float inputs the tests draw the
// reference is "exact" to far below the float bounds being checked. Each function returns all
// crossings of the *whole line* o + t d with the surface, sorted by t, with the unit outward
// normal there; the caller picks the one in its (tmin, tmax). Tangent contacts are reported
// once. Every function also returns `margin` >= 0, a lower bound of how far (in length units)
// the line is from changing its hit/miss classification (e.g. |r - closest distance| for a
// sphere; the distance of the crossing from the nearest edge line for a triangle), so a test
// can tell a
// legitimately ambiguous case (float rounding within the margin) from a wrong answer.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace reference {

using Real = long double;
using vec3l = glm::vec<3, Real, glm::defaultp>;

template <typename V>
inline vec3l widen(const V& v) {
    return vec3l(Real(v.x), Real(v.y), Real(v.z));
}

struct Crossing {
    Real t = 0;
    vec3l normal{0};  // unit outward normal (flat shapes: the shape's own normal)
    Real u = 0, v = 0;  // triangles: barycentrics of b and c; quads: (s, t); else 0
};

struct Crossings {
    std::vector<Crossing> hits;  // sorted by t
    Real margin = 0;             // >= 0; at most the distance to the hit/miss boundary
};

// Roots of |o + t d - c|^2 = r^2 computed stably (closest approach + same-sign sum).
inline Crossings sphere(const vec3l& o, const vec3l& d, const vec3l& c, Real r) {
    Crossings out;
    const vec3l f = o - c;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);
    const vec3l l = f - (b / a) * d;
    const Real l_len = std::sqrt(glm::dot(l, l));
    out.margin = std::fabs(r - l_len);
    if (l_len > r) return out;
    const Real root = std::sqrt(a * (r - l_len) * (r + l_len));
    const Real q = -(b + std::copysign(root, b));
    const Real cc = glm::dot(f, f) - r * r;
    Real t0 = q != 0 ? cc / q : 0, t1 = q != 0 ? q / a : 0;
    if (t0 > t1) std::swap(t0, t1);
    for (Real t : {t0, t1}) {
        if (!out.hits.empty() && out.hits.back().t == t) break;
        out.hits.push_back({t, (o + t * d - c) / r});
    }
    return out;
}

// Half-chord of the sphere crossing in length units (sqrt(r^2 - closest^2)); 0 on a miss.
inline Real sphere_half_chord(const vec3l& o, const vec3l& d, const vec3l& c, Real r) {
    const vec3l f = o - c;
    const vec3l l = f - (glm::dot(f, d) / glm::dot(d, d)) * d;
    const Real l_len = std::sqrt(glm::dot(l, l));
    return l_len < r ? std::sqrt((r - l_len) * (r + l_len)) : Real(0);
}

// The line against the triangle's plane, then signed-area barycentrics of the crossing.
// margin = smallest distance of the crossing point to the triangle's three edge lines
// (signed: negative when outside); no crossing when the line is parallel to the plane.
inline Crossings triangle(const vec3l& o, const vec3l& d, const vec3l& a, const vec3l& b, const vec3l& c) {
    Crossings out;
    const vec3l n = glm::cross(b - a, c - a);
    const Real nn = glm::dot(n, n);
    const Real nd = glm::dot(n, d);
    if (nn == 0 || nd == 0) return out;
    const Real t = glm::dot(n, a - o) / nd;
    const vec3l p = o + t * d;
    const Real w0 = glm::dot(n, glm::cross(c - b, p - b)) / nn;
    const Real w1 = glm::dot(n, glm::cross(a - c, p - c)) / nn;
    const Real w2 = glm::dot(n, glm::cross(b - a, p - a)) / nn;
    // Distance to an edge line = barycentric * height over that edge = w * 2 area / |edge|.
    const Real area2 = std::sqrt(nn);
    const Real m0 = w0 * area2 / glm::length(c - b);
    const Real m1 = w1 * area2 / glm::length(a - c);
    const Real m2 = w2 * area2 / glm::length(b - a);
    // Outside, the largest violation is a lower bound of the distance to the triangle.
    out.margin = std::fabs(std::min({m0, m1, m2}));
    if (w0 < 0 || w1 < 0 || w2 < 0) return out;
    out.hits.push_back({t, n / area2, w1, w2});
    return out;
}

}  // namespace reference

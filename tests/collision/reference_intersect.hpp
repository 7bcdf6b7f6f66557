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

// Which kind of surface a crossing is on; tests pick the matching stated bound by it.
enum class Part { flat, side, sphere };

struct Crossing {
    Real t = 0;
    vec3l normal{0};  // unit outward normal (flat shapes: the shape's own normal)
    Real u = 0, v = 0;  // triangles: barycentrics of b and c; quads: (s, t); else 0
    Part part = Part::flat;
    Real half_chord = 0;  // side/sphere: the exact half-chord sqrt(r^2 - closest^2) of that quadric
    vec3l center{0};      // sphere parts: the sphere's centre
};

struct Crossings {
    std::vector<Crossing> hits;  // sorted by t
    Real margin = 0;             // >= 0; see each function
    // Box and cylinder: the ends of the interval intersection that decides hit (enter <= exit)
    // or miss, also on a miss, with the axis (0-2; 3 = the cylinder side) that set each end.
    Real enter = 0, exit = 0;
    int enter_axis = -1, exit_axis = -1;
};

namespace detail {

// Roots of |f + t d|^2 = r^2 (any dimension), stably; false when the line misses (or d = 0).
// `closest` receives the closest-approach distance |l|.
template <typename V>
inline bool roots(const V& f, const V& d, Real r, Real& t0, Real& t1, Real& closest, Real& half_chord) {
    const Real a = glm::dot(d, d);
    if (a == 0) return false;
    const Real b = glm::dot(f, d);
    const V l = f - (b / a) * d;
    closest = std::sqrt(glm::dot(l, l));
    if (closest > r) return false;
    half_chord = std::sqrt((r - closest) * (r + closest));
    const Real q = -(b + std::copysign(std::sqrt(a) * half_chord, b));
    const Real c = glm::dot(f, f) - r * r;
    t0 = q != 0 ? c / q : 0;
    t1 = q != 0 ? q / a : 0;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

}  // namespace detail

// margin = |r - closest distance of the line to the centre|.
inline Crossings sphere(const vec3l& o, const vec3l& d, const vec3l& c, Real r) {
    Crossings out;
    Real t0, t1, closest = 0, h = 0;
    const bool hit = detail::roots(o - c, d, r, t0, t1, closest, h);
    out.margin = std::fabs(r - closest);
    if (!hit) return out;
    out.hits.push_back({t0, (o + t0 * d - c) / r, 0, 0, Part::sphere, h, c});
    if (t1 != t0) out.hits.push_back({t1, (o + t1 * d - c) / r, 0, 0, Part::sphere, h, c});
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

// Slab test on [c - size/2, c + size/2] (exact in long double). margin = the chord length
// |t_exit - t_enter| |d| (0 when tangent to an edge); misses through a zero-direction axis
// outside its slab get margin = the distance to that slab.
inline Crossings box(const vec3l& o, const vec3l& d, const vec3l& c, const vec3l& size) {
    Crossings out;
    const vec3l lo = c - size / Real(2), hi = c + size / Real(2);
    Real t_enter = -INFINITY, t_exit = INFINITY;
    int ae = -1, ax = -1;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0) {
            if (o[i] < lo[i] || o[i] > hi[i]) {
                out.margin = std::min(std::fabs(o[i] - lo[i]), std::fabs(o[i] - hi[i]));
                return out;
            }
            continue;
        }
        Real tn = (lo[i] - o[i]) / d[i], tf = (hi[i] - o[i]) / d[i];
        if (tn > tf) std::swap(tn, tf);
        if (tn > t_enter) t_enter = tn, ae = i;
        if (tf < t_exit) t_exit = tf, ax = i;
    }
    out.margin = std::fabs(t_exit - t_enter) * glm::length(d);
    out.enter = t_enter, out.exit = t_exit, out.enter_axis = ae, out.exit_axis = ax;
    if (t_enter > t_exit) return out;
    vec3l ne(0), nx(0);
    ne[ae] = d[ae] > 0 ? -1 : 1;
    nx[ax] = d[ax] > 0 ? 1 : -1;
    out.hits.push_back({t_enter, ne});
    if (t_exit != t_enter) out.hits.push_back({t_exit, nx});
    return out;
}

// Plane n.(x - p0) = 0; no crossing for a parallel line. margin: unused (infinite).
inline Crossings plane(const vec3l& o, const vec3l& d, const vec3l& p0, const vec3l& n) {
    Crossings out;
    out.margin = INFINITY;
    const Real nd = glm::dot(n, d);
    if (nd == 0) return out;
    out.hits.push_back({glm::dot(n, p0 - o) / nd, glm::normalize(n)});
    return out;
}

// Disk; margin = |rho - r| of the plane crossing.
inline Crossings disk(const vec3l& o, const vec3l& d, const vec3l& c, const vec3l& n, Real r) {
    Crossings out = plane(o, d, c, n);
    if (out.hits.empty()) return out;
    const Real rho = glm::length(o + out.hits[0].t * d - c);
    out.margin = std::fabs(rho - r);
    if (rho > r) out.hits.clear();
    return out;
}

// Parallelogram corner + s eu + t ev; margin = distance (in s, t units) to the nearest of the
// four edge lines, i.e. min(|s|, |1 - s|, |t|, |1 - t|).
inline Crossings quad(const vec3l& o, const vec3l& d, const vec3l& corner, const vec3l& eu, const vec3l& ev) {
    const vec3l n = glm::cross(eu, ev);
    Crossings out = plane(o, d, corner, n);
    if (out.hits.empty()) return out;
    const vec3l rel = o + out.hits[0].t * d - corner;
    const Real nn = glm::dot(n, n);
    const Real s = glm::dot(glm::cross(rel, ev), n) / nn, t = glm::dot(glm::cross(eu, rel), n) / nn;
    out.margin = std::min({std::fabs(s), std::fabs(1 - s), std::fabs(t), std::fabs(1 - t)});
    out.hits[0].u = s;
    out.hits[0].v = t;
    if (s < 0 || s > 1 || t < 0 || t > 1) out.hits.clear();
    return out;
}

// Y-aligned solid cylinder (centre, radius, full height): infinite cylinder x slab.
// margin = min(|r - closest distance to the axis|, chord length |t_exit - t_enter| |d|).
inline Crossings cylinder(const vec3l& o, const vec3l& d, const vec3l& c, Real r, Real h) {
    Crossings out;
    const glm::vec<2, Real> f2(o.x - c.x, o.z - c.z), d2(d.x, d.z);
    Real s0 = -INFINITY, s1 = INFINITY, closest = 0, chord = 0;
    bool side_hit = true;
    if (d2 == glm::vec<2, Real>(0)) {
        closest = glm::length(f2);
        side_hit = closest <= r;
    } else {
        side_hit = detail::roots(f2, d2, r, s0, s1, closest, chord);
    }
    out.margin = std::fabs(r - closest);
    if (!side_hit) return out;
    const Real ylo = c.y - h / 2, yhi = c.y + h / 2;
    Real c0 = -INFINITY, c1 = INFINITY;
    if (d.y != 0) {
        c0 = (ylo - o.y) / d.y;
        c1 = (yhi - o.y) / d.y;
        if (c0 > c1) std::swap(c0, c1);
    } else if (o.y < ylo || o.y > yhi) {
        out.margin = std::min(out.margin, std::min(std::fabs(o.y - ylo), std::fabs(o.y - yhi)));
        return out;
    }
    const bool enter_cap = c0 >= s0, exit_cap = c1 <= s1;
    const Real te = enter_cap ? c0 : s0, tx = exit_cap ? c1 : s1;
    out.margin = std::min(out.margin, std::fabs(tx - te) * glm::length(d));
    out.enter = te, out.exit = tx, out.enter_axis = enter_cap ? 1 : 3, out.exit_axis = exit_cap ? 1 : 3;
    if (te > tx) return out;
    const auto make = [&](Real t, bool cap, bool entering) {
        const vec3l p = o + t * d;
        if (cap) {
            const bool top = entering == (d.y < 0);
            return Crossing{t, vec3l(0, top ? 1 : -1, 0)};
        }
        const vec3l n = glm::normalize(vec3l(p.x - c.x, 0, p.z - c.z));
        return Crossing{t, n, 0, 0, Part::side, chord};
    };
    out.hits.push_back(make(te, enter_cap, true));
    if (tx != te) out.hits.push_back(make(tx, exit_cap, false));
    return out;
}

// Capsule around segment a-b (any orientation). The convex set's entry/exit: the infinite
// cylinder's, if within the segment's extent, else the end sphere's on that side.
// margin = |r - distance between the line and the segment|.
inline Crossings capsule(const vec3l& o, const vec3l& d, const vec3l& a, const vec3l& b, Real r) {
    Crossings out;
    const vec3l w = b - a;
    const Real ww = glm::dot(w, w);
    // Distance line-segment: minimise over s in [0, 1] the distance of a + s w to the line.
    {
        const vec3l dn = d / glm::length(d);
        const auto dist2 = [&](Real s) {
            const vec3l g = a + s * w - o;
            const Real along = glm::dot(g, dn);
            return glm::dot(g, g) - along * along;
        };
        Real s_best = 0;
        if (ww > 0) {
            const vec3l wp = w - glm::dot(w, dn) * dn, gp = (a - o) - glm::dot(a - o, dn) * dn;
            const Real den = glm::dot(wp, wp);
            s_best = den > 0 ? std::clamp(-glm::dot(gp, wp) / den, Real(0), Real(1)) : Real(0);
        }
        out.margin = std::fabs(r - std::sqrt(std::max(Real(0), dist2(s_best))));
    }
    const vec3l u = ww > 0 ? w / std::sqrt(ww) : vec3l(0, 1, 0);
    const vec3l f = o - a;
    const vec3l f_perp = f - glm::dot(f, u) * u, d_perp = d - glm::dot(d, u) * u;
    const bool parallel = glm::dot(d_perp, d_perp) == 0;
    Real s0 = 0, s1 = 0, closest = 0, chord = 0;
    if (parallel) {
        if (glm::length(f_perp) > r) return out;
    } else if (!detail::roots(f_perp, d_perp, r, s0, s1, closest, chord)) {
        return out;
    }
    const Real len = std::sqrt(ww);
    const auto end = [&](Real side_t, int which, Crossing& x) {
        bool at_a;
        if (parallel) {
            at_a = (which == 0) == (glm::dot(d, u) > 0);
        } else {
            const Real along = glm::dot(f + side_t * d, u);
            if (along >= 0 && along <= len) {
                const vec3l p = o + side_t * d;
                const vec3l q = a + along * u;
                x = Crossing{side_t, (p - q) / r, 0, 0, Part::side, chord};
                return true;
            }
            at_a = along < 0;
        }
        const vec3l e = at_a ? a : b;
        Real t0, t1, cl, hc;
        if (!detail::roots(o - e, d, r, t0, t1, cl, hc)) return false;
        const Real t = which == 0 ? t0 : t1;
        x = Crossing{t, (o + t * d - e) / r, 0, 0, Part::sphere, hc, e};
        return true;
    };
    Crossing c0, c1;
    if (!end(s0, 0, c0) || !end(s1, 1, c1)) return out;
    out.hits.push_back(c0);
    if (c1.t != c0.t) out.hits.push_back(c1);
    return out;
}

// Axis-aligned ellipsoid by scaling to the unit sphere; margin = |1 - closest| in the scaled
// space (unitless).
inline Crossings ellipsoid(const vec3l& o, const vec3l& d, const vec3l& c, const vec3l& radii) {
    const vec3l fs = (o - c) / radii, ds = d / radii;
    Crossings out = sphere(fs, ds, vec3l(0), 1);
    for (Crossing& x : out.hits) {
        x.normal = glm::normalize((fs + x.t * ds) / radii);
        x.center = c;
    }
    return out;
}

}  // namespace reference

// Translational triangle-triangle, swept (thesis 3.5.2: the problem the thesis could not solve).
//
// Under pure translation by v the first contact of two triangles is one of
//  - vertex-face: a vertex of the moving triangle reaches the still one (3 paths V + t v), or a
//    vertex of the still triangle is reached by the moving one (3 paths U - t v against the
//    moving triangle at its start);
//  - edge-edge: a moving edge P0 + t v + s a crosses a still edge Q0 + u b (9 pairs).
// Both are linear in the unknowns. Vertex-face: V + t v = A + beta e1 + gamma e2. Edge-edge:
// s a - u b + t v = Q0 - P0. The four points P0 + t v, P0 + a + t v, Q0, Q0 + b are coplanar
// when det(a, b, Q0 - P0 - t v) = 0, i.e. det(a, b, Q0 - P0) - t det(a, b, v) = 0: linear in t,
// so t = det(a, b, Q0 - P0) / det(a, b, v), and s, u follow by Cramer's rule; the contact is
// real when s, u are in [0, 1]. The earliest t in [0, 1] over the 15 features wins; this is the
// ray cast against the Minkowski difference of the two triangles (THESIS.md 3.5).
//
// Degenerate systems (determinant exactly 0) are exactly the motions parallel to a face (for
// vertex-face) or to the plane of both edges / parallel edges (for edge-edge). Then every
// isolated first contact is an endpoint of one segment reaching the other segment, handled by
// point_segment(): the thesis's "segment lying in the plane is ignored" is not ignored here.
//
// Already overlapping at t = 0 (Möller, overlap_triangle_triangle.cpp) -> t = 0.
// Result: point = the contact point (on the still triangle, at time t); normal = the still
// face's normal (vertex-face), the moving face's normal (still vertex on moving face), or
// a x b (edge-edge), turned to point against the motion (still -> moving); where none is
// defined (parallel edges, or overlap at t = 0 with no motion) see against_motion().
// At t = 0 the point is the still triangle's point nearest the moving triangle's centroid: a
// representative point, not necessarily inside the intersection.
//
// Precision: everything in double from float inputs. Each determinant carries ~10 roundings
// relative to the product of its columns' lengths; parameters are exact up to that divided by
// the determinant (ill-conditioned only near the degenerate motions above). A contact exactly
// on the boundary of a feature (s = 0, beta = 0) is also the contact of the neighbouring
// feature, so a parameter rounding just outside [0, 1] is caught there. t is then rounded to
// float (0.5 ulp). Degenerate input: a zero-area triangle or non-finite input -> no hit.
#include <array>

#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "collision/detail/swept_common.hpp"

namespace collision {
namespace {

using detail::dvec3;

struct Candidate {
    bool hit = false;
    double t = 0.0;
    dvec3 point{0.0};
    dvec3 normal{0.0};
};

void keep_earlier(Candidate& best, const Candidate& c) {
    if (c.hit && (!best.hit || c.t < best.t)) best = c;
}

// Solves x0 c0 + x1 c1 + x2 c2 = r by Cramer's rule; false when the determinant is exactly 0.
bool solve3(const dvec3& c0, const dvec3& c1, const dvec3& c2, const dvec3& r, double x[3]) {
    const dvec3 c12 = glm::cross(c1, c2);
    const double det = glm::dot(c0, c12);
    if (det == 0.0 || !std::isfinite(det)) return false;
    x[0] = glm::dot(r, c12) / det;
    x[1] = glm::dot(c0, glm::cross(r, c2)) / det;
    x[2] = glm::dot(c0, glm::cross(c1, r)) / det;
    return true;
}

bool in01(double x) { return x >= 0.0 && x <= 1.0; }

// Point p moving by w against segment [q, q + b], called only in the degenerate cases, where
// p, w and b are coplanar up to rounding: the first t in [0, 1] with p + t w on the segment.
// With r = p - q, r + t w = u b; crossing with b and with w gives
//   t = -(r x b).(w x b) / |w x b|^2,   u = -(r x w).(w x b) / |w x b|^2
// (no normal equations, whose cancellation squares the conditioning). The point must also lie
// in the plane of w and b: its distance |r . (w x b)| / |w x b| from it is computed with about
// 10 roundings relative to |r| |w| |b| / |w x b| (the plane is only as well defined as the angle
// between w and b), so the tolerance is 64 u (|r| + |w| + |b|) |w| |b| / |w x b|, u = 2^-53.
// The same tolerance admits u within rounding of [0, 1]. When w is parallel to b (w x b = 0),
// p slides along the segment's line if it is on it: u(t) is linear, its entry into [0, 1] wins.
bool point_segment(const dvec3& p, const dvec3& w, const dvec3& q, const dvec3& b, double& t_out) {
    const dvec3 r = p - q;
    const double bb = glm::dot(b, b);
    if (!(bb > 0.0) || !(glm::dot(w, w) > 0.0)) return false;
    const double lw = glm::length(w), lb = std::sqrt(bb);
    const double scale = glm::length(r) + lw + lb;
    const dvec3 wxb = glm::cross(w, b);
    const double det = glm::dot(wxb, wxb);
    double t, u;
    if (det > 0.0) {
        const double sin_len = std::sqrt(det);  // |w x b|
        const double tol = 64.0 * 0x1p-53 * scale * lw * lb / sin_len;
        if (std::abs(glm::dot(r, wxb)) / sin_len > tol) return false;  // not in the plane
        t = -glm::dot(glm::cross(r, b), wxb) / det;
        u = -glm::dot(glm::cross(r, w), wxb) / det;
        const double u_tol = tol / lb;
        if (!in01(t) || !(u >= -u_tol && u <= 1.0 + u_tol)) return false;
    } else {
        // Parallel: p must lie on the segment's line (distance to it within rounding).
        const double tol = 64.0 * 0x1p-53 * scale;
        const double u0 = glm::dot(r, b) / bb, du = glm::dot(w, b) / bb;
        if (glm::length(glm::cross(r, b)) / lb > tol) return false;
        if (u0 >= 0.0 && u0 <= 1.0) t = 0.0;
        else t = ((u0 < 0.0 ? 0.0 : 1.0) - u0) / du;
        if (!in01(t)) return false;
    }
    t_out = t;
    return true;
}

struct Tri {
    dvec3 v[3];
    dvec3 n;  // unnormalised (b - a) x (c - a)
};

// Vertex p moving by w against still triangle s; contact point = p + t w.
Candidate vertex_face(const dvec3& p, const dvec3& w, const Tri& s) {
    Candidate c;
    const dvec3 e1 = s.v[1] - s.v[0], e2 = s.v[2] - s.v[0];
    double x[3];  // beta, gamma, t
    if (solve3(e1, e2, -w, p - s.v[0], x)) {
        if (x[0] >= 0.0 && x[1] >= 0.0 && x[0] + x[1] <= 1.0 && in01(x[2])) {
            c.hit = true;
            c.t = x[2];
            c.point = s.v[0] + x[0] * e1 + x[1] * e2;
            c.normal = s.n;
        }
        return c;
    }
    // Motion parallel to the face: the vertex can only reach it across an edge, in the plane.
    for (int i = 0; i < 3; ++i) {
        double t;
        if (point_segment(p, w, s.v[i], s.v[(i + 1) % 3] - s.v[i], t) && (!c.hit || t < c.t)) {
            c.hit = true;
            c.t = t;
            c.point = p + t * w;
            c.normal = glm::cross(s.v[(i + 1) % 3] - s.v[i], s.n);  // in-plane, across the edge
        }
    }
    return c;
}

// Moving edge [p, p + a] by v against still edge [q, q + b].
Candidate edge_edge(const dvec3& p, const dvec3& a, const dvec3& v, const dvec3& q, const dvec3& b) {
    Candidate c;
    double x[3];  // s, u, t  in  s a - u b + t v = q - p
    if (solve3(a, -b, v, q - p, x)) {
        if (in01(x[0]) && in01(x[1]) && in01(x[2])) {
            c.hit = true;
            c.t = x[2];
            c.point = q + x[1] * b;
            c.normal = glm::cross(a, b);
        }
        return c;
    }
    // Degenerate: an endpoint of one edge reaches the other edge.
    const dvec3 n = glm::cross(a, b);
    auto consider = [&](bool ok, double t, const dvec3& point) {
        if (ok && (!c.hit || t < c.t)) {
            c.hit = true;
            c.t = t;
            c.point = point;
            c.normal = n;  // zero for parallel edges: against_motion() then uses -v
        }
    };
    double t;
    bool ok = point_segment(p, v, q, b, t);
    consider(ok, t, p + t * v);
    ok = point_segment(p + a, v, q, b, t);
    consider(ok, t, p + a + t * v);
    ok = point_segment(q, -v, p, a, t);
    consider(ok, t, q);
    ok = point_segment(q + b, -v, p, a, t);
    consider(ok, t, q + b);
    return c;
}

}  // namespace

TimeOfImpact sweep(const Triangle& moving, const glm::vec3& motion, const Triangle& still) {
    using namespace detail;
    if (!finite(moving.a) || !finite(moving.b) || !finite(moving.c) || !finite(still.a) || !finite(still.b) ||
        !finite(still.c) || !finite(motion))
        return {};
    Tri m{{to_double(moving.a), to_double(moving.b), to_double(moving.c)}, {}};
    Tri s{{to_double(still.a), to_double(still.b), to_double(still.c)}, {}};
    m.n = glm::cross(m.v[1] - m.v[0], m.v[2] - m.v[0]);
    s.n = glm::cross(s.v[1] - s.v[0], s.v[2] - s.v[0]);
    if (m.n == dvec3(0.0) || s.n == dvec3(0.0)) return {};

    if (triangles_overlap(m.v, s.v)) {
        const glm::vec3 centroid = (moving.a + moving.b + moving.c) / 3.0f;
        return overlapping_at_start(Contact{}, closest_point(still, centroid), s.n, motion);
    }
    const dvec3 v = to_double(motion);
    if (v == dvec3(0.0)) return {};

    Candidate best;
    for (int i = 0; i < 3; ++i) keep_earlier(best, vertex_face(m.v[i], v, s));
    for (int j = 0; j < 3; ++j) {
        Candidate c = vertex_face(s.v[j], -v, m);  // point: where the moving face meets s.v[j]...
        if (c.hit) c.point = s.v[j];               // ...which is the still vertex itself
        keep_earlier(best, c);
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            keep_earlier(best, edge_edge(m.v[i], m.v[(i + 1) % 3] - m.v[i], v, s.v[j], s.v[(j + 1) % 3] - s.v[j]));
    if (!best.hit) return {};
    TimeOfImpact r;
    r.hit = true;
    r.t = float(best.t);
    r.point = glm::vec3(best.point);
    r.normal = against_motion(best.normal, motion);
    return r;
}

}  // namespace collision

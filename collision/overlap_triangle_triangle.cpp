// Triangle-triangle, discrete (thesis 3.2.3): Möller, "A Fast Triangle-Triangle Intersection
// Test" (1997), plus the coplanar case the thesis leaves out.
//
//  1. Signed distances of each triangle's vertices to the other's plane; all strictly on one
//     side -> disjoint.
//  2. Otherwise both triangles cross the planes' intersection line L; each one's part on L is
//     an interval, found from the two edges crossing the other plane by similar triangles
//     (t = p0 + (p1 - p0) d0 / (d0 - d1); d0 and d1 have opposite signs, so no cancellation),
//     with the vertices projected on the largest axis of L's direction. Overlap of the
//     intervals (touching included) decides.
//  3. Coplanar triangles (all distances zero): project on the coordinate plane that drops the
//     normal's largest component and test the 2D triangles: any pair of edges intersecting, or
//     a vertex of one inside the other (Möller's own coplanar fallback).
//
// Precision and the one tolerance: computed in double from float inputs. A signed distance
// d = n . (v - a) with n = (b - a) x (c - a) carries, to first order, 3 roundings from the
// differences b - a, c - a, v - a, 2 in each cross-product component and 3 in the dot product,
// each of unit u = 2^-53 relative to the "permanent" P = |n|' . |v - a| (|n|' being the cross
// product of the edges' absolute values) -- the argument of Shewchuk's orient3d error bound.
// So |error| <= 8 u P (+ O(u^2)); we use 12 u P to cover the second-order terms with room.
// A distance within that bound has an uncertain sign and is treated as 0 (on the plane). That
// can only turn a "strictly apart" answer into "touching", never miss a contact: the test is
// conservative by at most 12 u P, ~1e-15 of the triangles' scale.
// Degenerate: a zero-area triangle (cross product exactly 0) or non-finite input -> false.
#include <cmath>

#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {
namespace detail {
namespace {

constexpr double unit_roundoff = 0x1p-53;

dvec3 abs_cross(const dvec3& a, const dvec3& b) {
    const dvec3 x = glm::abs(a), y = glm::abs(b);
    return {x.y * y.z + x.z * y.y, x.z * y.x + x.x * y.z, x.x * y.y + x.y * y.x};
}

// Signed distances (scaled by |n|) of v[0..2] to the plane of t, snapped to 0 within their
// rounding bound. Returns the plane normal.
dvec3 plane_distances(const dvec3 t[3], const dvec3 v[3], double d[3]) {
    const dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
    const dvec3 n = glm::cross(e1, e2);
    const dvec3 n_abs = abs_cross(e1, e2);
    for (int i = 0; i < 3; ++i) {
        const dvec3 w = v[i] - t[0];
        const double di = glm::dot(n, w);
        const double bound = 12.0 * unit_roundoff * glm::dot(n_abs, glm::abs(w));
        d[i] = std::abs(di) <= bound ? 0.0 : di;
    }
    return n;
}

bool strictly_one_side(const double d[3]) {
    return (d[0] > 0.0 && d[1] > 0.0 && d[2] > 0.0) || (d[0] < 0.0 && d[1] < 0.0 && d[2] < 0.0);
}

// Möller's interval of a triangle on the line, from projections p and plane distances d
// (not all zero, not all strictly on one side).
void line_interval(const double p[3], const double d[3], double& lo, double& hi) {
    int k;  // the vertex alone on its side of the other plane
    if (d[0] * d[1] > 0.0) k = 2;
    else if (d[0] * d[2] > 0.0) k = 1;
    else if (d[1] * d[2] > 0.0 || d[0] != 0.0) k = 0;
    else if (d[1] != 0.0) k = 1;
    else k = 2;
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double t1 = p[k] + (p[i] - p[k]) * (d[k] / (d[k] - d[i]));
    const double t2 = p[k] + (p[j] - p[k]) * (d[k] / (d[k] - d[j]));
    lo = std::min(t1, t2);
    hi = std::max(t1, t2);
}

struct P2 {
    double x, y;
};

double orient(const P2& a, const P2& b, const P2& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool within_box(const P2& a, const P2& b, const P2& p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

bool segments_meet(const P2& p1, const P2& p2, const P2& q1, const P2& q2) {
    const double o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2);
    const double o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
    return (o1 == 0 && within_box(p1, p2, q1)) || (o2 == 0 && within_box(p1, p2, q2)) ||
           (o3 == 0 && within_box(q1, q2, p1)) || (o4 == 0 && within_box(q1, q2, p2));
}

bool inside(const P2 t[3], const P2& p) {
    const double a = orient(t[0], t[1], p), b = orient(t[1], t[2], p), c = orient(t[2], t[0], p);
    return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
}

bool coplanar_overlap(const dvec3 a[3], const dvec3 b[3], const dvec3& n) {
    const dvec3 m = glm::abs(n);
    const int drop = (m.x >= m.y && m.x >= m.z) ? 0 : (m.y >= m.z ? 1 : 2);
    const int i0 = drop == 0 ? 1 : 0, i1 = drop == 2 ? 1 : 2;
    P2 p[3], q[3];
    for (int k = 0; k < 3; ++k) {
        p[k] = {a[k][i0], a[k][i1]};
        q[k] = {b[k][i0], b[k][i1]};
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (segments_meet(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3])) return true;
    return inside(q, p[0]) || inside(p, q[0]);
}

}  // namespace

bool triangles_overlap(const dvec3 a[3], const dvec3 b[3]) {
    for (int i = 0; i < 3; ++i)
        if (!finite(a[i]) || !finite(b[i])) return false;
    double db[3], da[3];
    const dvec3 na = plane_distances(a, b, db);
    const dvec3 nb = plane_distances(b, a, da);
    if (na == dvec3(0.0) || nb == dvec3(0.0)) return false;  // zero-area triangle
    if (strictly_one_side(db) || strictly_one_side(da)) return false;

    const dvec3 line = glm::cross(na, nb);
    const bool coplanar = (db[0] == 0.0 && db[1] == 0.0 && db[2] == 0.0) ||
                          (da[0] == 0.0 && da[1] == 0.0 && da[2] == 0.0) || line == dvec3(0.0);
    if (coplanar) return coplanar_overlap(a, b, na);

    const dvec3 m = glm::abs(line);
    const int axis = (m.x >= m.y && m.x >= m.z) ? 0 : (m.y >= m.z ? 1 : 2);
    const double pa[3] = {a[0][axis], a[1][axis], a[2][axis]};
    const double pb[3] = {b[0][axis], b[1][axis], b[2][axis]};
    double a_lo, a_hi, b_lo, b_hi;
    line_interval(pa, da, a_lo, a_hi);
    line_interval(pb, db, b_lo, b_hi);
    return std::max(a_lo, b_lo) <= std::min(a_hi, b_hi);
}

}  // namespace detail

bool overlap(const Triangle& a, const Triangle& b) {
    using detail::to_double;
    const detail::dvec3 ta[3] = {to_double(a.a), to_double(a.b), to_double(a.c)};
    const detail::dvec3 tb[3] = {to_double(b.a), to_double(b.b), to_double(b.c)};
    return detail::triangles_overlap(ta, tb);
}

}  // namespace collision

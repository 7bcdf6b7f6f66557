// Closest point of a triangle to a point (Ericson, Real-Time Collision Detection, 5.1.5): decide
// which Voronoi region of the triangle (3 vertices, 3 edges, face) holds p from dot products,
// then project onto that feature only. No division happens unless the denominator is a sum of
// positive terms of that region, so a zero-area triangle still returns one of its points
// (never NaN): a degenerate face region falls back to the nearest edge.
//
// Error: computed in double from float inputs (see detail/overlap_common.hpp); the returned point is
// within a few double ulps (relative to the triangle's size and |p|) of the exact closest point,
// then rounded to float once: |result - exact| <= 0.5 ulp(float) per component + ~1e-15 relative.
#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {
namespace detail {

dvec3 closest_on_triangle(const dvec3& a, const dvec3& b, const dvec3& c, const dvec3& p) {
    const dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;  // vertex region a

    const dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;  // vertex region b

    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;  // edge ab

    const dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;  // vertex region c

    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;  // edge ac

    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);  // edge bc

    const double sum = va + vb + vc;
    if (!(sum > 0.0)) {
        // Only a (numerically) zero-area triangle gets here with p outside every edge region:
        // the nearest of the three edges is the answer.
        const dvec3 e[3] = {closest_on_segment(a, b, p), closest_on_segment(a, c, p), closest_on_segment(b, c, p)};
        dvec3 best = e[0];
        for (const dvec3& q : e)
            if (glm::dot(q - p, q - p) < glm::dot(best - p, best - p)) best = q;
        return best;
    }
    const double v = vb / sum, w = vc / sum;  // face region
    return a + ab * v + ac * w;
}

}  // namespace detail

glm::vec3 closest_point(const Triangle& tri, const glm::vec3& p) {
    using detail::to_double;
    return glm::vec3(detail::closest_on_triangle(to_double(tri.a), to_double(tri.b), to_double(tri.c), to_double(p)));
}

}  // namespace collision

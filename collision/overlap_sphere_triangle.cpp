// Sphere-triangle, discrete (thesis 3.2.4, after Ericson). The thesis projects the centre on the
// plane, tests barycentrics, and falls back to the three edges; the closest point of the
// triangle to the centre (Ericson 5.1.5, closest_point_triangle.cpp) answers all of that at once
// and also covers the vertex regions. Overlap (touching included) when that point is within the
// radius; the minimal translation is exact (push_out: the sphere is a point in the triangle
// grown by r, a convex set).
// Departures: a centre lying on the triangle (where the direction would be a zero vector) is
// pushed along the triangle's front normal (b - a) x (c - a) by r. Degenerate: radius <= 0,
// zero-area triangle (cross product exactly 0 in double) or non-finite input gives hit = false.
#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {
namespace detail {

Contact sphere_triangle(const dvec3& center, double radius, const dvec3& a, const dvec3& b, const dvec3& c) {
    const dvec3 n = glm::cross(b - a, c - a);
    const double n2 = glm::dot(n, n);
    if (!(n2 > 0.0) || !std::isfinite(n2)) return {};
    return push_out(center - closest_on_triangle(a, b, c, center), radius, n / std::sqrt(n2));
}

}  // namespace detail

Contact overlap(const Sphere& s, const Triangle& tri) {
    using namespace detail;
    if (!valid_radius(s.radius) || !finite(s.center) || !finite(tri.a) || !finite(tri.b) || !finite(tri.c)) return {};
    return sphere_triangle(to_double(s.center), s.radius, to_double(tri.a), to_double(tri.b), to_double(tri.c));
}

}  // namespace collision

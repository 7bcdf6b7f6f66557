#pragma once
// Helpers shared by the discrete tests (overlap_*.cpp) and the swept tests built on them.
//
// Why double: every discrete test converts its float inputs to double first. Differences of two
// floats are then exact (unless their exponents differ by more than 29), and products of two
// such differences are exact too (2 x 25 significant bits < 53), so a decision such as
// |c1 - c2|^2 <= (r1 + r2)^2 carries only a few double roundings, about 1e-16 relative to the
// quantities compared: the float inputs are, in effect, decided exactly unless they touch to
// within ~1e-16 relative. The result is rounded to float once at the end.
#include <cmath>

#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

#include "collision/finite.hpp"
#include "collision/hit.hpp"

namespace collision::detail {

using dvec3 = glm::dvec3;

inline dvec3 to_double(const glm::vec3& v) { return dvec3(v); }

// A radius is usable when it is finite and strictly positive (NaN fails the comparison).
inline bool valid_radius(float r) { return r > 0.0f && std::isfinite(r); }

// A Y-aligned cylinder or capsule is usable with a positive radius, height >= 0 (height 0 is a
// disk or a sphere) and finite centre.
inline bool valid_upright(const glm::vec3& center, float radius, float height) {
    return valid_radius(radius) && height >= 0.0f && std::isfinite(height) && finite(center);
}

// A box is usable with a finite centre and finite sizes >= 0 (a zero size is a flat box).
inline bool valid_box(const glm::vec3& center, const glm::vec3& size) {
    return finite(center) && finite(size) && size.x >= 0.0f && size.y >= 0.0f && size.z >= 0.0f;
}

// The point-versus-(convex set grown by a ball) contact, which every round shape pair reduces
// to. `offset` = p - q, where q is the point of the convex core nearest to p; the grown set is
// everything within `radius` of the core. For p inside, the nearest boundary point is
// p + (radius - |offset|) * offset / |offset| (distance to the core is 1-Lipschitz, so no
// boundary point is nearer): that is the exact minimal translation vector. When p lies on the
// core (|offset| = 0) every direction normal to the core is equally short and the caller's
// unit `fallback` is used, so no zero vector is ever normalised.
inline Contact push_out(const dvec3& offset, double radius, const dvec3& fallback) {
    Contact c;
    const double d2 = glm::dot(offset, offset);
    if (!(d2 <= radius * radius)) return c;  // also rejects NaN
    const double d = std::sqrt(d2);
    const dvec3 dir = d > 0.0 ? offset / d : fallback;
    c.hit = true;
    c.displacement = glm::vec3(dir * (radius - d));
    return c;
}

// Closest point of segment [a, b] to p (Ericson 5.1.2), clamped parameter; a == b is a point.
inline dvec3 closest_on_segment(const dvec3& a, const dvec3& b, const dvec3& p) {
    const dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    if (!(len2 > 0.0)) return a;
    double s = glm::dot(p - a, ab) / len2;
    s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
    return a + s * ab;
}

// Closest point of triangle abc to p (Ericson 5.1.5, Voronoi regions), in double.
dvec3 closest_on_triangle(const dvec3& a, const dvec3& b, const dvec3& c, const dvec3& p);

// Sphere (centre, radius > 0) against triangle abc, exact minimal translation of the sphere;
// hit = false for a zero-area triangle (overlap_sphere_triangle.cpp).
Contact sphere_triangle(const dvec3& center, double radius, const dvec3& a, const dvec3& b, const dvec3& c);

// Möller triangle-triangle overlap with the coplanar case, touching included
// (overlap_triangle_triangle.cpp); false when either triangle has zero area.
bool triangles_overlap(const dvec3 a[3], const dvec3 b[3]);

}  // namespace collision::detail

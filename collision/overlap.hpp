#pragma once
// Discrete tests (§3.1, §3.2): do two shapes overlap now, and by how much.
// `Contact::displacement` is the minimal translation of the *first* argument that separates
// them (the thesis's Data). Degenerate input (radius <= 0, NaN, zero-area triangle) returns
// hit = false, never NaN. Implementations: overlap_<pair>.cpp.
#include <optional>

#include "collision/hit.hpp"
#include "collision/shapes.hpp"

namespace collision {

Contact overlap(const Sphere& a, const Sphere& b);
Contact overlap(const Aabb& a, const Aabb& b);
Contact overlap(const Cylinder& a, const Cylinder& b);
Contact overlap(const Capsule& a, const Capsule& b);
Contact overlap(const Sphere& s, const Triangle& tri);
Contact overlap(const Ellipsoid& e, const Triangle& tri);

// Möller 1997, with the coplanar case (2D edge tests) the thesis leaves out.
bool overlap(const Triangle& a, const Triangle& b);

// The intersection line of two planes; nullopt when they are parallel (or coincident).
std::optional<Line> intersect(const Plane& a, const Plane& b);

// Closest point of triangle to p (Ericson 5.1.5); used by the sphere/ellipsoid tests.
glm::vec3 closest_point(const Triangle& tri, const glm::vec3& p);

}  // namespace collision

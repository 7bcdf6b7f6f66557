#pragma once
// Thesis-faithful swept tests (collision::thesis), beside collision/swept.hpp. Only the pairs
// whose continuous method in the thesis differs from the default beyond the ray test itself:
// for box, cylinder and capsule the reduction (one cast against the summed shape) is the same,
// and the thesis's difference is all in thesis::intersect (collision/thesis/intersect.hpp).
//  - sweep(Sphere, v, Sphere): §3.1.2, the segment against the sphere of radius r1 + r2 by the
//    textbook quadratic (thesis::intersect).
//  - sweep(Sphere, v, Triangle): §3.2.5, two offset triangles by plane + barycentrics and three
//    edge capsules rotated to Y by an angle (thesis::intersect); a path in the triangle's plane
//    is rejected by the segment-plane step and only the capsules can catch it.
//  - sweep(Ellipsoid, v, Triangle): §3.2.6, scaled to the unit sphere, the thesis sphere sweep,
//    and the resulting normal scaled back by the radii as the thesis scales its vector (the
//    correct map for a normal divides by them: see swept_ellipsoid_triangle.cpp).
// None checks for overlap at t = 0 first (the thesis's continuous tests did not): a start
// inside gives whatever the ray test gives for an inside origin. point = the still shape's
// point nearest the moving centre at contact; normal = the ray test's normal as returned.
#include "collision/hit.hpp"
#include "collision/shapes.hpp"

namespace collision::thesis {

TimeOfImpact sweep(const Sphere& moving, const glm::vec3& motion, const Sphere& still);
TimeOfImpact sweep(const Sphere& moving, const glm::vec3& motion, const Triangle& still);
TimeOfImpact sweep(const Ellipsoid& moving, const glm::vec3& motion, const Triangle& still);

}  // namespace collision::thesis

#pragma once
// Thesis-faithful ray-shape tests: the methods of the thesis's §3.1-3.2 as written there,
// kept beside the robust defaults (collision/intersect.hpp) as the "before" of the accuracy
// charts. Same signatures and the same RayHit fields, but:
//  - no error analysis: point_error is always 0 (the thesis has no notion of it), the point is
//    o + t d as computed, not re-projected;
//  - no input validation: degenerate shapes and non-finite input go through the formulas; the
//    IEEE results (inf, NaN, a division by zero) are the thesis's behaviour and each file says
//    what comes out; NaN can reach t, point or normal only where a file says so;
//  - the thesis's own weaknesses are kept on purpose (each file names them); tests in
//    tests/collision/test_intersect_thesis.cpp assert that they show.
// "Nearest" among several candidate hits means the smallest t in (tmin, tmax), the thesis's
// "closest to the start of the segment".
#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "collision/shapes.hpp"

namespace collision::thesis {

// §3.1.2: textbook quadratic, c = p1.p1 + q.q - 2 p1.q - r^2.
bool intersect(const Ray& ray, const Sphere& s, RayHit& hit);
// §3.1.4: the six face planes, each hit kept if inside its bounded face.
bool intersect(const Ray& ray, const Aabb& box, RayHit& hit);
// §3.1.4 (cylinder): the two caps by segment-plane + distance < r, the side in 2D (x, z) by
// the textbook quadratic, skipped when the origin is inside the infinite cylinder.
bool intersect(const Ray& ray, const Cylinder& c, RayHit& hit);
// §3.1.5: the two end spheres and the cylinder, each by its thesis test; nearest wins.
bool intersect(const Ray& ray, const Capsule& c, RayHit& hit);
// §3.2.5: rotate into the capsule's frame by the angle to (0,1,0) about (0,1,0) x axis
// (default axis (1,0,0) when the angle is 0 or pi), Y-aligned test, rotate back.
bool intersect(const Ray& ray, const OrientedCapsule& c, RayHit& hit);
// §3.2.6: scale by 1 / radii to the unit sphere, the thesis sphere test, scale back by radii.
bool intersect(const Ray& ray, const Ellipsoid& e, RayHit& hit);
// §3.2.5 segment-plane: t = n.(p - o) / n.d, rejected when n.d is exactly 0.
bool intersect(const Ray& ray, const Plane& p, RayHit& hit);
// The cylinder's cap test on its own: segment-plane, then distance to the centre < r.
bool intersect(const Ray& ray, const Disk& d, RayHit& hit);
// §3.2.5 segment-triangle: the plane, then Ericson's barycentric coordinates (§2.4) in [0, 1].
bool intersect(const Ray& ray, const Triangle& tri, RayHit& hit);

}  // namespace collision::thesis

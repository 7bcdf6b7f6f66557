#pragma once
// Ray-shape intersection: the thesis's continuous tests seen as ray casts (§3.1, §3.2).
//
// Contract for every overload:
//  - returns true and writes `hit` only for the nearest hit with ray.tmin < t < ray.tmax;
//    `hit` is left untouched otherwise;
//  - a ray starting inside a closed shape hits its far side (the exit point);
//  - rays parallel to faces, caps and planes get a defined answer: no division by zero ever
//    reaches the result;
//  - degenerate shapes (radius <= 0, zero-area triangle/quad, zero direction, NaN or infinite
//    input) return false and never produce NaN;
//  - each implementation file states the bound on t and on the hit point it guarantees, and
//    tests/collision checks it against a long double reference.
// Implementations: one file per shape, intersect_<shape>.cpp.
#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "collision/shapes.hpp"

namespace collision {

bool intersect(const Ray& ray, const Sphere& s, RayHit& hit);
bool intersect(const Ray& ray, const Aabb& box, RayHit& hit);
bool intersect(const Ray& ray, const Cylinder& c, RayHit& hit);
bool intersect(const Ray& ray, const Capsule& c, RayHit& hit);
bool intersect(const Ray& ray, const OrientedCapsule& c, RayHit& hit);
bool intersect(const Ray& ray, const Ellipsoid& e, RayHit& hit);
bool intersect(const Ray& ray, const Plane& p, RayHit& hit);
bool intersect(const Ray& ray, const Disk& d, RayHit& hit);
bool intersect(const Ray& ray, const Quad& q, RayHit& hit);
bool intersect(const Ray& ray, const Triangle& tri, RayHit& hit);

// Slab test for acceleration structures: does the ray meet the box [lo, hi] with
// t in [ray.tmin, ray.tmax]? Conservative (never misses a box the exact ray meets), given
// precomputed inverse direction (may hold infinities for zero components).
bool intersect_slab(const Ray& ray, const glm::vec3& inv_dir, const glm::vec3& lo, const glm::vec3& hi,
                    float& t_enter, float& t_exit);

}  // namespace collision

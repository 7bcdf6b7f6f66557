// Sphere-triangle, swept (thesis 3.2.5). The Minkowski sum of a triangle and a ball of radius r
// is bounded by the triangle offset by +-r along its unit normal and by three capsules of
// radius r around the edges (their end spheres are the vertex spheres). The sphere's centre
// path is cast against those five parts -- watertight ray-triangle (intersect_triangle.cpp) and
// ray-oriented-capsule (intersect_oriented_capsule.cpp) -- and the nearest hit wins: from a
// start outside the sum, the first surface met is the sum's boundary.
// Departures: the thesis rejected a path lying in the triangle's plane (denominator 0), and
// rotated each capsule to Y by an angle and axis (thesis::intersect for OrientedCapsule). Here
// the in-plane path is caught by the edge capsules, and the capsule test needs no rotation.
// Already overlapping (discrete test, touching included) -> t = 0.
// Result: normal = outward normal of the part hit (still -> moving): +-n for the faces, radial
// for the capsules; point = the triangle's point nearest the centre at contact (on both).
// t error: the larger of the two intersectors' stated bounds for the parts' sizes.
// Degenerate: radius <= 0, zero-area triangle, non-finite input -> no hit.
#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "collision/detail/swept_common.hpp"

namespace collision {

TimeOfImpact sweep(const Sphere& moving, const glm::vec3& motion, const Triangle& still) {
    using namespace detail;
    if (!finite(motion)) return {};
    const dvec3 a = to_double(still.a), b = to_double(still.b), c = to_double(still.c);
    const dvec3 n = glm::cross(b - a, c - a);
    const Contact now = overlap(moving, still);  // also rejects degenerate input
    if (now.hit) return overlapping_at_start(now, closest_point(still, moving.center), n, motion);
    if (!valid_radius(moving.radius) || !finite(moving.center) || !finite(still.a) || !finite(still.b) ||
        !finite(still.c) || !(glm::dot(n, n) > 0.0))
        return {};

    const float r = moving.radius;
    const glm::vec3 offset = glm::vec3(glm::normalize(n)) * r;
    const Ray ray = motion_ray(moving.center, motion);
    RayHit best;
    const bool found = nearest_on_grown_triangle(
        ray, still, offset, r, true, [](const Ray& q, const Triangle& t, RayHit& h) { return intersect(q, t, h); },
        [](const Ray& q, const OrientedCapsule& c, RayHit& h) { return intersect(q, c, h); }, best);
    if (!found) return {};
    TimeOfImpact res;
    res.hit = true;
    // An exit (normal along the motion): an intersector judged the start inside a part.
    res.t = glm::dot(best.normal, motion) > 0.0f ? 0.0f : std::min(best.t, 1.0f);
    res.normal = best.normal;
    res.point = closest_point(still, moving.center + motion * res.t);
    return res;
}

}  // namespace collision

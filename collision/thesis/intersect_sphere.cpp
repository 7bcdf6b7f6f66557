// Thesis §3.1.2 (sphere-sphere, continuous) as a ray cast: the textbook quadratic of
// detail::textbook_roots with c = p1.p1 + q.q - 2 p1.q - r^2, the root nearest the start in
// (tmin, tmax) wins.
// Weaknesses kept (measured in tests/collision/test_intersect_thesis.cpp): for a far origin or
// a far/huge sphere, p1.p1, q.q and 2 p1.q are each ~|p1|^2 or ~|q|^2 and c, their difference,
// keeps only the last bits: at |p1| = 1e5 and r = 1 the rounding of c (~1e3) exceeds r^2
// itself, so hits are lost or their t is far off. The point is o + t d (not on the sphere), the
// normal normalize(point - centre), point_error 0.
// Degenerate input: radius 0 gives the tangent point with a NaN normal (normalize of 0) when
// the line passes through the centre; a zero direction gives NaN roots, which never pass the
// range test (no hit); NaN input: no hit (the comparisons fail).
#include "collision/detail/ray_quadric.hpp"
#include "collision/thesis/intersect.hpp"
#include "collision/thesis/detail/textbook.hpp"

namespace collision::thesis {

bool intersect(const Ray& ray, const Sphere& s, RayHit& hit) {
    float t0, t1;
    if (!detail::textbook_roots(ray.origin, ray.dir, s.center, s.radius, t0, t1)) return false;
    detail::Nearest best;
    for (const float t : {t0, t1}) best.offer(ray, t, [] {});
    if (!best.finish(ray, hit)) return false;
    hit.normal = glm::normalize(hit.point - s.center);
    hit.uv = collision::detail::sphere_uv(hit.normal);
    return true;
}

}  // namespace collision::thesis

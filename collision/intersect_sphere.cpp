// Ray-sphere intersection, robust default (thesis §3.1 "sphere-sphere, continuous" as a ray cast).
//
// Method. With f = o - c, a = d.d, b = f.d (half the textbook b) the roots of
// a t^2 + 2 b t + (f.f - r^2) = 0 are wanted. Two cancellations ruin the textbook form for far
// origins and huge spheres (see collision/thesis/intersect_sphere.cpp):
//  - the discriminant b^2 - a (f.f - r^2) subtracts two numbers of size |f|^2 |d|^2 when only
//    r^2 - |l|^2 survives. We compute it from the closest-approach offset
//    l = f - (b / a) d (the perpendicular part of f, Ray Tracing Gems ch. 7, pbrt-v4) as
//    disc = a (r - |l|)(r + |l|), whose error is relative to r |l|, not to |f|^2;
//  - -b +- sqrt(disc) cancels for one root: q = -(b + sign(b) sqrt(disc)), t0 = c / q,
//    t1 = q / a takes each root from a sum of same-signed terms.
// The hit point o + t d is then re-projected on the sphere, p = c + r normalize(p - c), which
// puts it on the surface up to a few roundings however inaccurate t was (pbrt-v4 §6.8.5).
//
// Error bounds (float, inputs exact floats; eps = 2^-24, gamma(n) = n eps / (1 - n eps)).
//  t:  |t - t_exact| <= gamma(32) ((|f| + r)(1 + r / h) / |d| + |t|), where h = sqrt(r^2 - |l|^2)
//      is the exact half-chord. Counting roundings: f carries eps |f|, b gamma(4) |f||d|,
//      b / a and l gamma(10) |f|, so r^2 - |l|^2 carries about gamma(12) r (|f| + r); the root
//      divides that by 2 h (the derivative of the quadratic at the root) and by |d|; the final
//      division/sum add gamma(3) |t|. That gives gamma(16); the stated bound doubles it so the
//      rough count stays conservative. The factor r / h is the real conditioning of a grazing
//      hit: as the ray becomes tangent, no float method can pin t down better.
//  point: per axis, |point_i - s_i| <= point_error_i for a point s exactly on the sphere:
//      normalize() and the scaling by r cost gamma(6) |r n_i|, adding c one more rounding of
//      |point_i|; we store gamma(7) |r n_i| + gamma(2) |point_i|. This bounds the distance to
//      the *surface* (what offsetting the next ray needs); along the surface the point is as
//      good as t (bound above times |d|).
//  normal: unit to gamma(6), outward (c -> point), also for rays starting inside.
//  uv: not computed here (left 0): collision::surface_uv(shape, hit) gives it on request (surface_uv.hpp).
// Split for a BVH's inner loop (decide, then finish the nearest): sphere_candidate.hpp.
// Degenerate input: radius <= 0, NaN or infinite radius/centre/origin/direction, zero direction,
// or coordinates so large that squares overflow float (beyond ~1e18) give false.
#include "collision/intersect.hpp"
#include "collision/sphere_candidate.hpp"

namespace collision {

bool intersect(const Ray& ray, const Sphere& s, RayHit& hit) {
    float t;
    if (!intersect_sphere_candidate(ray, s, t)) return false;
    finish_sphere_hit(ray, s, t, hit);
    return true;
}

}  // namespace collision

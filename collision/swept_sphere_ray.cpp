// A moving sphere against a still line: when does the line pass through the sphere?
//
// Method: in the line's frame (unit direction u = dir / |dir|), the sphere's centre relative to
// the line's origin, w(t) = (centre - origin) + t motion, has the part perpendicular to the line
// w_perp(t) = w_perp + t v_perp, and the line meets the sphere while |w_perp(t)|^2 <= r^2: the
// quadratic a t^2 - 2 b t + c <= 0 with a = |v_perp|^2, b = w_perp . v_perp, c = |w_perp|^2 - r^2,
// solved in double with the cancellation-free root pair (q = b + sign(b) sqrt(b^2 - a c), roots
// q / a and c / q) and clipped to [0, 1].
//
// Error bound: the float inputs are exact in double and every intermediate is a sum of a few
// products (about a dozen roundings of 2^-53), so the quadratic f(t) = a t^2 - 2 b t + c is
// evaluated within eps M, eps < 2e-15, M = a t^2 + 2 |b t| + |w_perp|^2 + r^2 (the magnitudes
// of its terms), and a root t* moves by at most eps M / |f'(t*)| = eps M / (2 sqrt(b^2 - a c)).
// Away from tangency (where the interval shrinks to a point and any error is that of a grazing
// ray) this is far below the final rounding to float, half an ulp of t. The tests
// (tests/collision/test_swept_sphere_ray.cpp) restate it: each end within 2 float ulps of a
// long-double reference on seeded cases with sqrt(b^2 - a c) > 1e-6 M.
//
// Degenerate input: a zero direction or radius <= 0 or a non-finite input gives no interval;
// motion parallel to the line (a = 0) gives [0, 1] when the line passes through the sphere and
// nothing otherwise.
#include <cmath>

#include <glm/geometric.hpp>

#include "collision/finite.hpp"
#include "collision/swept.hpp"

namespace collision {

TimeInterval sweep_interval(const Sphere& moving, const glm::vec3& motion, const Ray& line) {
    TimeInterval out;
    if (!(moving.radius > 0.0f) || !finite(moving.center) || !finite(motion) || !finite(line.origin) || !finite(line.dir))
        return out;
    const glm::dvec3 dir(line.dir);
    const double len2 = glm::dot(dir, dir);
    if (!(len2 > 0.0)) return out;
    const glm::dvec3 u = dir / std::sqrt(len2);
    const glm::dvec3 w = glm::dvec3(moving.center) - glm::dvec3(line.origin);
    const glm::dvec3 v(motion);
    const glm::dvec3 w_perp = w - glm::dot(w, u) * u;
    const glm::dvec3 v_perp = v - glm::dot(v, u) * u;
    const double r = moving.radius;
    const double a = glm::dot(v_perp, v_perp);
    const double b = -glm::dot(w_perp, v_perp);  // |w_perp + t v_perp|^2 = a t^2 - 2 b t + |w_perp|^2
    const double c = glm::dot(w_perp, w_perp) - r * r;
    double t0, t1;
    if (!(a > 0.0)) {
        if (!(c <= 0.0)) return out;
        t0 = 0.0;
        t1 = 1.0;
    } else {
        const double disc = b * b - a * c;
        if (disc < 0.0) return out;
        const double q = b + std::copysign(std::sqrt(disc), b);
        if (q == 0.0) {  // b = 0 and disc = 0: a tangent at t = 0
            t0 = t1 = 0.0;
        } else {
            t0 = q / a;
            t1 = c / q;
            if (t0 > t1) std::swap(t0, t1);
        }
    }
    if (t1 < 0.0 || t0 > 1.0) return out;
    out.hit = true;
    out.t0 = static_cast<float>(t0 < 0.0 ? 0.0 : t0);
    out.t1 = static_cast<float>(t1 > 1.0 ? 1.0 : t1);
    return out;
}

}  // namespace collision

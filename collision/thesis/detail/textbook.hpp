#pragma once
// The two formulas the thesis's ray tests are built from, written as the thesis writes them.
#include <cmath>
#include <initializer_list>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "collision/hit.hpp"
#include "collision/ray.hpp"

namespace collision::thesis::detail {

// §3.1.2, segment p1 + t (p2 - p1) against the sphere |x - q| = r (also used in 2D for the
// cylinder side): a = d.d, b = 2 d.(p1 - q), c = p1.p1 + q.q - 2 p1.q - r^2,
// t = (-b +- sqrt(b^2 - 4 a c)) / 2a. Both roots, t0 <= t1 when a > 0; false when
// b^2 - 4ac < 0. Weaknesses kept: c cancels catastrophically when |p1| or |q| is large
// against r (p1.p1 and q.q are each ~|p1|^2), b^2 - 4ac cancels for far origins, and
// -b + sqrt(...) cancels for the near root. a = 0 (zero direction) divides by zero: t0, t1
// are +-inf or NaN.
template <typename Vec>
inline bool textbook_roots(const Vec& p1, const Vec& d, const Vec& q, float r, float& t0, float& t1) {
    const float a = glm::dot(d, d);
    const float b = 2.0f * glm::dot(d, p1 - q);
    const float c = glm::dot(p1, p1) + glm::dot(q, q) - 2.0f * glm::dot(p1, q) - r * r;
    const float disc = b * b - 4.0f * a * c;
    if (disc < 0.0f) return false;
    const float root = std::sqrt(disc);
    t0 = (-b - root) / (2.0f * a);
    t1 = (-b + root) / (2.0f * a);
    return true;
}

// §3.2.5 segment-plane: d = n.(p1 - p0); "if the result is zero the segment is parallel to the
// plane and we reject" (exactly zero: a segment lying in the plane is ignored, as the thesis
// admits); t = n.(point - p0) / d.
inline bool segment_plane(const Ray& ray, const glm::vec3& point, const glm::vec3& n, float& t) {
    const float denom = glm::dot(n, ray.dir);
    if (denom == 0.0f) return false;
    t = glm::dot(n, point - ray.origin) / denom;
    return true;
}

// Candidate bookkeeping: keep the smallest t in (tmin, tmax).
struct Nearest {
    float t = 0.0f;
    bool found = false;
    template <typename F>
    void offer(const Ray& ray, float candidate, F&& fill) {
        if (candidate > ray.tmin && candidate < ray.tmax && (!found || candidate < t)) {
            t = candidate;
            found = true;
            fill();
        }
    }
    // Writes the winner's t and the thesis's point o + t d (no error bound: 0).
    bool finish(const Ray& ray, RayHit& hit) const {
        if (!found) return false;
        hit.t = t;
        hit.point = ray.at(t);
        hit.point_error = glm::vec3(0.0f);
        return true;
    }
};

}  // namespace collision::thesis::detail

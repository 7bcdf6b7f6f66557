#pragma once
// Helpers shared by the swept tests (swept_*.cpp). Each swept test first asks the discrete test
// whether the shapes already overlap (-> t = 0), then casts the moving centre's path as a ray
// over [0, 1] against the Minkowski sum of the two shapes.
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"
#include "collision/hit.hpp"
#include "collision/intersect.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision::detail {

// The motion segment as a ray. tmax is one float above 1 so a contact exactly at t = 1 (the
// intersectors accept only t < tmax) is found; results are clamped to 1.
inline Ray motion_ray(const glm::vec3& start, const glm::vec3& motion) {
    return Ray{start, motion, 0.0f, next_float_up(1.0f)};
}

// A unit vector `n` turned to point against the motion (from the still shape toward the moving
// one, which approaches from that side). With no usable n the reversed motion is used, and with
// no motion either, +Y: the normal is never NaN.
inline glm::vec3 against_motion(const dvec3& n, const glm::vec3& motion) {
    const double len2 = glm::dot(n, n);
    if (len2 > 0.0 && std::isfinite(len2)) {
        dvec3 u = n / std::sqrt(len2);
        if (glm::dot(u, dvec3(motion)) > 0.0) u = -u;
        return glm::vec3(u);
    }
    const float m2 = glm::dot(motion, motion);
    if (m2 > 0.0f && std::isfinite(m2)) return -motion / std::sqrt(m2);
    return {0.0f, 1.0f, 0.0f};
}

// The t = 0 answer when the discrete test says the shapes overlap: the normal is the direction
// of the minimal translation vector (still -> moving) when it has one, otherwise
// `fallback_normal` turned against the motion.
inline TimeOfImpact overlapping_at_start(const Contact& c, const glm::vec3& point, const dvec3& fallback_normal,
                                         const glm::vec3& motion) {
    TimeOfImpact r;
    r.hit = true;
    r.t = 0.0f;
    r.point = point;
    const dvec3 d(c.displacement);
    r.normal = glm::dot(d, d) > 0.0 ? glm::vec3(glm::normalize(d)) : against_motion(fallback_normal, motion);
    return r;
}

// Ray cast of the moving centre against the grown (Minkowski sum) shape. A hit whose normal
// faces along the motion is an exit: the intersector judged the start inside the grown shape
// (the discrete test, rounding differently, did not) -- reported as contact at t = 0.
// `contact_point(p, n)` maps the centre at contact and the normal to a point of contact.
template <class Grown, class PointFn>
TimeOfImpact cast_against(const glm::vec3& start, const glm::vec3& motion, const Grown& grown, PointFn contact_point) {
    TimeOfImpact r;
    RayHit h;
    if (!intersect(motion_ray(start, motion), grown, h)) return r;
    r.hit = true;
    r.t = glm::dot(h.normal, motion) > 0.0f ? 0.0f : std::min(h.t, 1.0f);
    r.normal = h.normal;
    r.point = contact_point(start + motion * r.t, h.normal);
    return r;
}

// The nearest hit of `ray` on the parts bounding a triangle grown by a ball (thesis 3.2.5): the
// triangle moved by +offset and -offset (offset = unit normal * radius) and the three edge
// capsules of that radius, each cast with the given ray tests (robust or thesis). With
// `face_normals_outward` the faces' normals are set to +-offset's direction (the grown set's
// outward side); otherwise the triangle test's normal is kept as returned.
template <class TriangleTest, class CapsuleTest>
bool nearest_on_grown_triangle(const Ray& ray, const Triangle& t, const glm::vec3& offset, float radius,
                               bool face_normals_outward, TriangleTest triangle_test, CapsuleTest capsule_test,
                               RayHit& best) {
    bool found = false;
    auto consider = [&](bool hit, const RayHit& h) {
        if (hit && (!found || h.t < best.t)) {
            best = h;
            found = true;
        }
    };
    for (const float side : {1.0f, -1.0f}) {
        const glm::vec3 o = offset * side;
        RayHit h;
        const bool hit = triangle_test(ray, Triangle{t.a + o, t.b + o, t.c + o}, h);
        if (face_normals_outward) h.normal = glm::normalize(o);
        consider(hit, h);
    }
    const glm::vec3 v[3] = {t.a, t.b, t.c};
    for (int i = 0; i < 3; ++i) {
        RayHit h;
        consider(capsule_test(ray, OrientedCapsule{v[i], v[(i + 1) % 3], radius}, h), h);
    }
    return found;
}

inline bool earlier(const TimeOfImpact& a, const TimeOfImpact& b) { return a.hit && (!b.hit || a.t < b.t); }

}  // namespace collision::detail

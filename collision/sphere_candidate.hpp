#pragma once
// intersect(Ray, Sphere) of intersect_sphere.cpp split for a BVH's inner loop, as
// triangle_watertight.hpp splits the triangle test: the candidate step decides the hit and its
// t (every check of the full test, so a candidate is always a hit, with the same t), and finish
// computes the point, its error and the normal once, for the nearest candidate. Method and error
// bounds: intersect_sphere.cpp; intersect(Ray, Sphere) is candidate + finish.
//   float t;
//   if (intersect_sphere_candidate(ray, sphere, t)) { ray.tmax = t; keep (sphere, ray) }
//   ... finish_sphere_hit(kept ray, sphere, t, hit);   // the same hit intersect() gives
#include <cmath>

#include <glm/geometric.hpp>

#include "collision/detail/ray_quadric.hpp"
#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "collision/shapes.hpp"

namespace collision {

inline bool intersect_sphere_candidate(const Ray& ray, const Sphere& s, float& t) {
    const float r = s.radius;
    if (!(r > 0.0f) || !std::isfinite(r)) return false;
    float t0, t1;
    if (!detail::stable_roots(ray.origin - s.center, ray.dir, r, t0, t1)) return false;
    if (!detail::pick_root(t0, t1, ray, t)) return false;
    // reproject_on_sphere's own check (finish cannot fail on a candidate).
    const glm::vec3 v = ray.at(t) - s.center;
    const float v_len2 = glm::dot(v, v);
    return v_len2 > 0.0f && std::isfinite(v_len2);
}

// `t` from intersect_sphere_candidate on the same ray and sphere.
inline void finish_sphere_hit(const Ray& ray, const Sphere& s, float t, RayHit& hit) {
    glm::vec3 n, point, point_error;
    detail::reproject_on_sphere(ray.at(t), s.center, s.radius, n, point, point_error);
    hit.t = t;
    hit.point = point;
    hit.point_error = point_error;
    hit.normal = n;
    hit.uv = glm::vec2(0.0f);
}

}  // namespace collision

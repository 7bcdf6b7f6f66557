// Ray-box intersection, robust default: the slab test (Kay & Kajiya) with exact face distances,
// instead of the thesis's six face planes (collision/thesis/intersect_aabb.cpp).
//
// Per axis i the ray is inside the slab [lo_i, hi_i] for t between (lo_i - o_i) / d_i and
// (hi_i - o_i) / d_i; the box is the intersection of the three slabs, the ray's part of it
// [t_enter, t_exit] = [max of the near ends, min of the far ends]. A zero d_i is handled
// explicitly (no 0 * inf): the slab is all t when lo_i <= o_i <= hi_i (a ray lying in a face
// plane touches the box, closed-set semantics) and empty otherwise.
// Nearest hit: t_enter if in (tmin, tmax), else t_exit (a ray starting inside hits the far
// side). The normal is the face of the axis that set that end; ties (edges, corners) go to the
// lowest axis index (x before y before z).
//
// Error bounds (eps = 2^-24, gamma(n) = n eps / (1 - n eps)). lo = centre - size / 2 costs one
// rounding (eps |lo|; size / 2 is exact). t = (face - o_i) / d_i then costs two more:
//  t:  |t - t_exact| <= gamma(3) (|t| + |face_i| / |d_i|), i the axis of the face hit.
//  point: the face coordinate is written exactly (the computed face), the two others are
//      o + t d clamped to the computed face rectangle, so the point lies on the computed box
//      surface; point_error = gamma(2) |point| per axis covers the computed box's rounding.
// normal: +-unit axis.  uv: the other two coordinates in ascending axis order, as fractions
//     (x_j - lo_j) / size_j of the face.
// Degenerate: any size <= 0 or non-finite, non-finite centre/origin/direction, zero
// direction: false.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include "collision/finite.hpp"
#include "collision/float_error.hpp"
#include "collision/intersect.hpp"

namespace collision {

bool intersect(const Ray& ray, const Aabb& box, RayHit& hit) {
    if (!(box.size.x > 0.0f && box.size.y > 0.0f && box.size.z > 0.0f)) return false;
    if (!finite(box.size) || !finite(box.center) || !finite(ray.origin) || !finite(ray.dir)) return false;
    if (ray.dir == glm::vec3(0.0f)) return false;
    const glm::vec3 lo = box.min(), hi = box.max();
    float t_enter = -std::numeric_limits<float>::infinity(), t_exit = std::numeric_limits<float>::infinity();
    int axis_enter = -1, axis_exit = -1;
    for (int i = 0; i < 3; ++i) {
        const float o = ray.origin[i], d = ray.dir[i];
        if (d == 0.0f) {
            if (o < lo[i] || o > hi[i]) return false;
            continue;
        }
        float t_near = (lo[i] - o) / d, t_far = (hi[i] - o) / d;
        if (d < 0.0f) std::swap(t_near, t_far);
        // Strict comparisons keep the lowest axis on ties.
        if (t_near > t_enter) { t_enter = t_near; axis_enter = i; }
        if (t_far < t_exit) { t_exit = t_far; axis_exit = i; }
    }
    if (t_enter > t_exit) return false;
    float t;
    int axis;
    bool entering;
    if (t_enter > ray.tmin && t_enter < ray.tmax) {
        t = t_enter, axis = axis_enter, entering = true;
    } else if (t_exit > ray.tmin && t_exit < ray.tmax) {
        t = t_exit, axis = axis_exit, entering = false;
    } else {
        return false;
    }
    // axis >= 0 here: with a non-zero direction some axis sets each finite end, and an infinite
    // end never passes the range test above.
    const float sign_d = ray.dir[axis] > 0.0f ? 1.0f : -1.0f;
    const float outward = entering ? -sign_d : sign_d;  // entering against d, leaving along it
    glm::vec3 p = ray.at(t);
    p = glm::clamp(p, lo, hi);
    p[axis] = outward > 0.0f ? hi[axis] : lo[axis];
    hit.t = t;
    hit.point = p;
    hit.point_error = gamma(2) * glm::abs(p);
    hit.normal = glm::vec3(0.0f);
    hit.normal[axis] = outward;
    const int j = axis == 0 ? 1 : 0, k = axis == 2 ? 1 : 2;
    hit.uv = glm::vec2((p[j] - lo[j]) / box.size[j], (p[k] - lo[k]) / box.size[k]);
    return true;
}

}  // namespace collision

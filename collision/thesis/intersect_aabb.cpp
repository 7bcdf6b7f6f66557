// Thesis §3.1.4 (box-box, continuous) as a ray cast: each of the six faces is extended to its
// plane, the line is intersected with it (detail::segment_plane: exactly parallel faces are
// skipped, so there is no division by zero), the point o + t d is kept if it lies inside the
// bounded face (lo <= p <= hi on the two other axes), and the candidate nearest the start in
// (tmin, tmax) wins.
// Weaknesses kept: the inside-face check runs on the rounded point o + t d, so a ray through an
// edge or corner can land just outside both faces that meet there and pass through the box
// (a leak the slab test cannot have); six divisions and point evaluations instead of three.
// The normal is the face's (+-unit axis), point o + t d, point_error 0.
// Degenerate input: sizes <= 0 give an inside-out box whose faces are still tested; NaN input:
// no hit (the comparisons fail); a zero direction: every face is parallel, no hit.
#include <algorithm>

#include "collision/thesis/intersect.hpp"
#include "collision/thesis/detail/textbook.hpp"

namespace collision::thesis {

bool intersect(const Ray& ray, const Aabb& box, RayHit& hit) {
    const glm::vec3 lo = box.min(), hi = box.max();
    detail::Nearest best;
    for (int axis = 0; axis < 3; ++axis) {
        for (const float side : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = side;
            glm::vec3 face_point = box.center;
            face_point[axis] = side > 0.0f ? hi[axis] : lo[axis];
            float t;
            if (!detail::segment_plane(ray, face_point, n, t)) continue;
            const glm::vec3 p = ray.at(t);
            const int j = (axis + 1) % 3, k = (axis + 2) % 3;
            if (!(p[j] >= lo[j] && p[j] <= hi[j] && p[k] >= lo[k] && p[k] <= hi[k])) continue;
            best.offer(ray, t, [&] {
                hit.normal = n;
                hit.uv = glm::vec2((p[std::min(j, k)] - lo[std::min(j, k)]) / box.size[std::min(j, k)],
                                   (p[std::max(j, k)] - lo[std::max(j, k)]) / box.size[std::max(j, k)]);
            });
        }
    }
    return best.finish(ray, hit);
}

}  // namespace collision::thesis

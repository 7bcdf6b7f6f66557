// Thesis §3.1.4 (cylinder-cylinder, continuous) as a ray cast, in its three parts:
//  - caps: the cap plane by detail::segment_plane (parallel: skipped), accepted when the point
//    is closer than r to the cap's centre ("menší jak rádius": strictly);
//  - side: drop y and intersect the 2D line with the circle by the textbook quadratic
//    (detail::textbook_roots in 2D), accepted when the point's y lies between the caps; the
//    side is skipped when the origin lies inside the infinite cylinder, because "no point can
//    cross the side without first meeting a cap";
//  - the candidate nearest the start in (tmin, tmax) wins.
// Weaknesses kept: that skip is right for a segment that starts *outside* the cylinder but
// inside its infinite extension; a ray that starts inside the cylinder and leaves through the
// side finds no side hit (it reports a far cap or nothing). The 2D quadratic has the sphere's
// cancellations. Normal: caps (0, +-1, 0), side normalize((p - c) with y = 0); point o + t d,
// point_error 0.
// Degenerate input: no validation; NaN input: no hit; radius 0: the side test can return the
// tangent point with a NaN normal.
#include <glm/vec2.hpp>

#include "collision/detail/ray_quadric.hpp"
#include "collision/thesis/intersect.hpp"
#include "collision/thesis/detail/textbook.hpp"

namespace collision::thesis {

bool intersect(const Ray& ray, const Cylinder& cyl, RayHit& hit) {
    const float ylo = cyl.center.y - 0.5f * cyl.height, yhi = cyl.center.y + 0.5f * cyl.height;
    detail::Nearest best;
    for (const float side : {-1.0f, 1.0f}) {
        const glm::vec3 cap_center(cyl.center.x, side > 0.0f ? yhi : ylo, cyl.center.z);
        const glm::vec3 n(0.0f, side, 0.0f);
        float t;
        if (!detail::segment_plane(ray, cap_center, n, t)) continue;
        const glm::vec3 p = ray.at(t);
        if (!(glm::length(p - cap_center) < cyl.radius)) continue;
        best.offer(ray, t, [&] {
            hit.normal = n;
            hit.uv = glm::vec2((p.x - cyl.center.x) / (2.0f * cyl.radius) + 0.5f,
                               (p.z - cyl.center.z) / (2.0f * cyl.radius) + 0.5f);
        });
    }
    const glm::vec2 o2(ray.origin.x, ray.origin.z), d2(ray.dir.x, ray.dir.z), c2(cyl.center.x, cyl.center.z);
    const glm::vec2 rel = o2 - c2;
    const bool inside_infinite = glm::dot(rel, rel) < cyl.radius * cyl.radius;
    float t0, t1;
    if (!inside_infinite && detail::textbook_roots(o2, d2, c2, cyl.radius, t0, t1)) {
        for (const float t : {t0, t1}) {
            const glm::vec3 p = ray.at(t);
            if (!(p.y >= ylo && p.y <= yhi)) continue;
            best.offer(ray, t, [&] {
                hit.normal = glm::normalize(glm::vec3(p.x - cyl.center.x, 0.0f, p.z - cyl.center.z));
                hit.uv = glm::vec2(collision::detail::turn_fraction(hit.normal.z, hit.normal.x), (p.y - ylo) / cyl.height);
            });
        }
    }
    return best.finish(ray, hit);
}

}  // namespace collision::thesis

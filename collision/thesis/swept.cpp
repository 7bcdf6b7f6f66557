// Thesis 3.1.2, 3.2.5 and 3.2.6, continuous, as written there; see swept.hpp beside this file.
#include "collision/thesis/swept.hpp"

#include <glm/geometric.hpp>

#include "collision/overlap.hpp"
#include "collision/ray.hpp"
#include "collision/detail/swept_common.hpp"
#include "collision/thesis/intersect.hpp"

namespace collision::thesis {
namespace {

TimeOfImpact from_hit(const RayHit& h, const glm::vec3& point) {
    TimeOfImpact r;
    r.hit = true;
    r.t = h.t;
    r.normal = h.normal;
    r.point = point;
    return r;
}

}  // namespace

TimeOfImpact sweep(const Sphere& moving, const glm::vec3& motion, const Sphere& still) {
    RayHit h;
    if (!thesis::intersect(segment(moving.center, moving.center + motion), Sphere{still.center, moving.radius + still.radius}, h))
        return {};
    return from_hit(h, still.center + glm::normalize(h.point - still.center) * still.radius);
}

TimeOfImpact sweep(const Sphere& moving, const glm::vec3& motion, const Triangle& still) {
    const Ray ray = segment(moving.center, moving.center + motion);
    const glm::vec3 offset = glm::normalize(glm::cross(still.b - still.a, still.c - still.a)) * moving.radius;
    RayHit best;
    const bool found = collision::detail::nearest_on_grown_triangle(
        ray, still, offset, moving.radius, false,
        [](const Ray& q, const Triangle& t, RayHit& h) { return thesis::intersect(q, t, h); },
        [](const Ray& q, const OrientedCapsule& c, RayHit& h) { return thesis::intersect(q, c, h); }, best);
    if (!found) return {};
    return from_hit(best, closest_point(still, ray.at(best.t)));
}

TimeOfImpact sweep(const Ellipsoid& moving, const glm::vec3& motion, const Triangle& still) {
    const glm::vec3 inv = 1.0f / moving.radii;
    auto scale = [&](const glm::vec3& p) { return moving.center + (p - moving.center) * inv; };
    TimeOfImpact r = sweep(Sphere{moving.center, 1.0f}, motion * inv, Triangle{scale(still.a), scale(still.b), scale(still.c)});
    if (!r.hit) return r;
    r.point = moving.center + (r.point - moving.center) * moving.radii;
    r.normal = glm::normalize(r.normal * moving.radii);
    return r;
}

}  // namespace collision::thesis

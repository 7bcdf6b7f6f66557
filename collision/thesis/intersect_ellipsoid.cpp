// Thesis §3.2.6 (ellipsoid, by scaling) as a ray cast: scale space about the centre by
// 1 / radii so the ellipsoid becomes the unit sphere at the same centre, run the thesis's
// sphere test there (t is unchanged by the scaling), then scale the results back by radii, as
// the thesis scales its result vector back by (w, h, d).
// Weaknesses kept: the textbook sphere test's cancellations, now with the centre q = c kept
// at its world position (q.q ~ |c|^2 against r^2 = 1 in c); and scaling the normal back by
// radii is the thesis's way with vectors, but normals transform by the inverse transpose
// (1 / radii): on a non-spherical ellipsoid the thesis normal leans the wrong way (away from
// the long axis's flat sides). point_error 0.
#include <glm/geometric.hpp>

#include "collision/thesis/intersect.hpp"

namespace collision::thesis {

bool intersect(const Ray& ray, const Ellipsoid& e, RayHit& hit) {
    const Ray scaled{e.center + (ray.origin - e.center) / e.radii, ray.dir / e.radii, ray.tmin, ray.tmax};
    RayHit unit;
    if (!intersect(scaled, Sphere{e.center, 1.0f}, unit)) return false;
    hit = unit;
    hit.point = e.center + (unit.point - e.center) * e.radii;
    hit.normal = glm::normalize(unit.normal * e.radii);
    hit.point_error = glm::vec3(0.0f);
    return true;
}

}  // namespace collision::thesis

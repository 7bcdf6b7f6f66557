#pragma once
// Swept (continuous) tests (§2.2, §3.1, §3.2, §3.5.2): `moving` translates by `motion` over one
// step, t in [0, 1]; `still` does not move. Each reduces to a ray cast against the Minkowski sum
// (or difference) of the two shapes. The result is the first t at which the shapes touch; if
// they already overlap at t = 0 the result is t = 0 with hit = true.
// Implementations: swept_<pair>.cpp.
#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "collision/shapes.hpp"

namespace collision {

TimeOfImpact sweep(const Sphere& moving, const glm::vec3& motion, const Sphere& still);
TimeOfImpact sweep(const Aabb& moving, const glm::vec3& motion, const Aabb& still);
TimeOfImpact sweep(const Cylinder& moving, const glm::vec3& motion, const Cylinder& still);
TimeOfImpact sweep(const Capsule& moving, const glm::vec3& motion, const Capsule& still);
TimeOfImpact sweep(const Sphere& moving, const glm::vec3& motion, const Triangle& still);
TimeOfImpact sweep(const Ellipsoid& moving, const glm::vec3& motion, const Triangle& still);
// Translational triangle-triangle, which the thesis could not solve: the first contact is a
// vertex-face contact (6 vertex paths) or an edge-edge contact (9 edge pairs).
TimeOfImpact sweep(const Triangle& moving, const glm::vec3& motion, const Triangle& still);

// A closed time interval [t0, t1] within [0, 1]; hit = false when empty.
struct TimeInterval {
    bool hit = false;
    float t0 = 0.0f, t1 = 0.0f;
};

// The times at which a sphere moving by `motion` over the step meets the line through `line`
// (origin + s dir for every s: its tmin and tmax are not applied), the sphere's silhouette seen
// along a ray: in the ray's frame the centre's distance to the line is quadratic in t.
// Motion blur's closed form: a camera ray sees a linearly moving sphere for t1 - t0 of the
// shutter (swept_sphere_ray.cpp states the bound).
TimeInterval sweep_interval(const Sphere& moving, const glm::vec3& motion, const Ray& line);

}  // namespace collision

// Ellipsoid-triangle, swept (thesis 3.2.6 with 3.2.5): scale space about the ellipsoid's
// starting centre by 1 / radii, which maps the ellipsoid to the unit sphere, the triangle to
// the scaled triangle and the motion to motion / radii, run the swept sphere-triangle test
// there, and map the result back. Exact: the scaling is linear, so it keeps contact and keeps
// the time t (unlike the discrete test's displacement vector, see overlap_ellipsoid_triangle).
// Result: t unchanged; point = centre + radii * point'; normal = normalize(normal' / radii)
// (normals map by the inverse transpose of the scaling). t error: the sphere test's, for the
// scaled shapes (plus the float rounding of the scaled triangle, 0.5 ulp per coordinate).
// Degenerate: any radius <= 0, zero-area triangle, non-finite input -> no hit.
#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "collision/detail/swept_common.hpp"

namespace collision {

TimeOfImpact sweep(const Ellipsoid& moving, const glm::vec3& motion, const Triangle& still) {
    using namespace detail;
    if (!valid_radius(moving.radii.x) || !valid_radius(moving.radii.y) || !valid_radius(moving.radii.z)) return {};
    if (!finite(moving.center) || !finite(motion)) return {};
    const dvec3 c = to_double(moving.center), r = to_double(moving.radii);
    auto scale = [&](const glm::vec3& p) { return glm::vec3((to_double(p) - c) / r); };
    const Triangle scaled{scale(still.a), scale(still.b), scale(still.c)};
    TimeOfImpact res = sweep(Sphere{{0, 0, 0}, 1.0f}, glm::vec3(to_double(motion) / r), scaled);
    if (!res.hit) return res;
    res.point = glm::vec3(c + to_double(res.point) * r);
    res.normal = glm::vec3(glm::normalize(to_double(res.normal) / r));
    return res;
}

}  // namespace collision

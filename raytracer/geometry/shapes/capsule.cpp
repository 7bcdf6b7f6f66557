#include "raytracer/geometry/shapes/capsule.hpp"

#include <cmath>

#include "raytracer/geometry/shapes/rounded_bounds.hpp"
#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

using collision::gamma;

collision::Bounds3 CapsuleShape::object_bounds(const Geometry& c) {
    // 0.5 h + r rounds once; one more outward step covers it.
    return centred_bounds(c.center, glm::vec3(c.radius, collision::next_float_up(0.5f * c.height + c.radius), c.radius));
}

ShapeLight CapsuleShape::light(const Geometry& c, const Transform& xf, const std::vector<Mesh>&) {
    ShapeLight l = object_space_light(xf, ShapeLight::Strategy::ObjectArea);
    const float object_area = 2.0f * kPi * c.radius * (2.0f * c.radius + c.height);
    l.area_pdf = 1.0f / object_area;
    l.area = object_area_stand_in(object_area, l.inv_abs_det);
    return l;
}

void CapsuleShape::sample(const Geometry& c, const ShapeLight&, float u_part, float u1, float u2, SurfacePoint& out) {
    const float side_area = c.height, sphere_area = 2.0f * c.radius;  // both divided by 2 pi r
    if (u_part * (side_area + sphere_area) < side_area) {
        const float phi = 2.0f * kPi * u2;
        out.normal = glm::vec3(std::cos(phi), 0.0f, std::sin(phi));
        out.point = c.center + glm::vec3(c.radius * out.normal.x, (u1 - 0.5f) * c.height, c.radius * out.normal.z);
    } else {
        out.normal = uniform_sphere(u1, u2);
        const float cap = out.normal.y >= 0.0f ? 0.5f * c.height : -0.5f * c.height;
        out.point = c.center + glm::vec3(0.0f, cap, 0.0f) + c.radius * out.normal;
    }
    out.error = gamma(4) * (glm::abs(c.center) + glm::vec3(c.radius + c.height));
}

}  // namespace sweeptrace

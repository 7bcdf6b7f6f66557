#include "raytracer/geometry/shapes/cylinder.hpp"

#include <cmath>

#include "raytracer/geometry/shapes/rounded_bounds.hpp"
#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

using collision::gamma;

collision::Bounds3 CylinderShape::object_bounds(const Geometry& c) {
    return centred_bounds(c.center, glm::vec3(c.radius, 0.5f * c.height, c.radius));
}

ShapeLight CylinderShape::light(const Geometry& c, const Transform& xf, const std::vector<Mesh>&) {
    ShapeLight l = object_space_light(xf, ShapeLight::Strategy::ObjectArea);
    const float object_area = 2.0f * kPi * c.radius * (c.radius + c.height);
    l.area_pdf = 1.0f / object_area;
    l.area = object_area_stand_in(object_area, l.inv_abs_det);
    return l;
}

void CylinderShape::sample(const Geometry& c, const ShapeLight&, float u_part, float u1, float u2, SurfacePoint& out) {
    const float side_area = c.height, cap_area = 0.5f * c.radius;  // both divided by 2 pi r
    const float x = u_part * (side_area + 2.0f * cap_area);
    if (x < side_area) {
        const float phi = 2.0f * kPi * u2;
        out.normal = glm::vec3(std::cos(phi), 0.0f, std::sin(phi));
        out.point = c.center + glm::vec3(c.radius * out.normal.x, (u1 - 0.5f) * c.height, c.radius * out.normal.z);
    } else {
        const float sign = (x < side_area + cap_area) ? 1.0f : -1.0f;
        const glm::vec2 d = c.radius * concentric_disk(u1, u2);
        out.normal = glm::vec3(0.0f, sign, 0.0f);
        out.point = c.center + glm::vec3(d.x, sign * 0.5f * c.height, d.y);
    }
    out.error = gamma(4) * (glm::abs(c.center) + glm::vec3(c.radius + c.height));
}

}  // namespace sweeptrace

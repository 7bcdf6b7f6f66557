#include "raytracer/geometry/shapes/box.hpp"

#include "raytracer/geometry/shapes/rounded_bounds.hpp"

namespace sweeptrace {

using collision::gamma;

collision::Bounds3 BoxShape::object_bounds(const Geometry& b) {
    return centred_bounds(b.center, 0.5f * b.size);  // halving is exact
}

ShapeLight BoxShape::light(const Geometry& b, const Transform& xf, const std::vector<Mesh>&) {
    ShapeLight l = object_space_light(xf, ShapeLight::Strategy::ObjectArea);
    const glm::vec3 z = b.size;
    const float object_area = 2.0f * (z.y * z.z + z.x * z.z + z.x * z.y);
    l.area_pdf = 1.0f / object_area;
    l.area = object_area_stand_in(object_area, l.inv_abs_det);
    return l;
}

void BoxShape::sample(const Geometry& b, const ShapeLight&, float u_part, float u1, float u2, SurfacePoint& out) {
    const glm::vec3 z = b.size;
    const float areas[3] = {z.y * z.z, z.x * z.z, z.x * z.y};
    float x = u_part * (areas[0] + areas[1] + areas[2]);
    int axis = 0;
    while (axis < 2 && x >= areas[axis]) x -= areas[axis++];
    const float side = (x < 0.5f * areas[axis]) ? -1.0f : 1.0f;
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    glm::vec3 local(0.0f);
    local[axis] = 0.5f * side * z[axis];
    local[a1] = (u1 - 0.5f) * z[a1];
    local[a2] = (u2 - 0.5f) * z[a2];
    out.point = b.center + local;
    out.normal = glm::vec3(0.0f);
    out.normal[axis] = side;
    out.error = gamma(2) * (glm::abs(b.center) + z);
}

}  // namespace sweeptrace

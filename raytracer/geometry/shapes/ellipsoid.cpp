#include "raytracer/geometry/shapes/ellipsoid.hpp"

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "raytracer/geometry/shapes/rounded_bounds.hpp"
#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

using collision::gamma;

collision::Bounds3 EllipsoidShape::object_bounds(const Geometry& e) { return centred_bounds(e.center, e.radii); }

ShapeLight EllipsoidShape::light(const Geometry& e, const Transform& xf, const std::vector<Mesh>&) {
    ShapeLight l = object_space_light(xf, ShapeLight::Strategy::ObjectArea);
    const glm::vec3 origin = transform_point(xf.to_world, e.center);
    l.linear = l.linear * glm::mat3(glm::vec3(e.radii.x, 0, 0), glm::vec3(0, e.radii.y, 0), glm::vec3(0, 0, e.radii.z));
    l.to_world = glm::mat4(l.linear);
    l.to_world[3] = glm::vec4(origin, 1.0f);
    l.normal_to_world = glm::inverseTranspose(l.linear);
    l.inv_abs_det = 1.0f / std::abs(glm::determinant(l.linear));
    l.area_pdf = 1.0f / (4.0f * kPi);
    l.area = object_area_stand_in(4.0f * kPi, l.inv_abs_det);
    return l;
}

// The unit sphere: the radii and the centre are folded into l.to_world.
void EllipsoidShape::sample(const Geometry&, const ShapeLight&, float, float u1, float u2, SurfacePoint& out) {
    out.normal = uniform_sphere(u1, u2);
    out.point = out.normal;
    out.error = glm::vec3(gamma(3));
}

}  // namespace sweeptrace

#include "raytracer/geometry/shapes/disk.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/geometry/shapes/rounded_bounds.hpp"
#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

using collision::gamma;

collision::Bounds3 DiskShape::object_bounds(const Geometry& d) {
    // A disk's extent along axis a is r sqrt(1 - n_a^2) for unit n; the computed value is
    // enlarged by a relative gamma(4) (square, subtraction, sqrt, product) plus one ulp of r for
    // n_a = 1 exactly, where it may round to 0 a touch early.
    glm::vec3 half;
    const glm::vec3 n = glm::normalize(d.normal);
    for (int a = 0; a < 3; ++a) {
        const float e = d.radius * std::sqrt(std::fmax(0.0f, 1.0f - n[a] * n[a]));
        half[a] = e * (1.0f + gamma(4)) + d.radius * gamma(2);
    }
    return centred_bounds(d.center, half);
}

ShapeLight DiskShape::light(const Geometry& d, const Transform& xf, const std::vector<Mesh>&) {
    ShapeLight l;
    l.strategy = ShapeLight::Strategy::WorldArea;
    const glm::mat3 lin(xf.to_world);
    const Frame f(glm::normalize(d.normal));
    l.origin = transform_point(xf.to_world, d.center);
    l.edge_u = lin * (d.radius * f.s);
    l.edge_v = lin * (d.radius * f.t);
    l.normal = glm::normalize(xf.normal_to_world * f.n);
    l.area = kPi * glm::length(glm::cross(l.edge_u, l.edge_v));
    l.area_pdf = 1.0f / l.area;
    return l;
}


}  // namespace sweeptrace

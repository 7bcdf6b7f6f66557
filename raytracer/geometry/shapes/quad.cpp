#include "raytracer/geometry/shapes/quad.hpp"

#include <glm/geometric.hpp>

#include "raytracer/geometry/shapes/rounded_bounds.hpp"

namespace sweeptrace {

using collision::gamma;

collision::Bounds3 QuadShape::object_bounds(const Geometry& q) {
    collision::Bounds3 b;
    b.extend(q.corner);
    b.extend(q.corner + q.edge_u);
    b.extend(q.corner + q.edge_v);
    b.extend(q.corner + q.edge_u + q.edge_v);
    return padded_bounds(b, glm::abs(q.corner) + glm::abs(q.edge_u) + glm::abs(q.edge_v));
}

ShapeLight QuadShape::light(const Geometry& q, const Transform& xf, const std::vector<Mesh>&) {
    ShapeLight l;
    l.strategy = ShapeLight::Strategy::WorldArea;
    const glm::mat3 lin(xf.to_world);
    l.origin = transform_point(xf.to_world, q.corner);
    l.edge_u = lin * q.edge_u;
    l.edge_v = lin * q.edge_v;
    l.normal = glm::normalize(xf.normal_to_world * glm::cross(q.edge_u, q.edge_v));
    l.area = glm::length(glm::cross(l.edge_u, l.edge_v));
    l.area_pdf = 1.0f / l.area;
    return l;
}


}  // namespace sweeptrace

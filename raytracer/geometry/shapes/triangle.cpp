#include "raytracer/geometry/shapes/triangle.hpp"

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"
#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

using collision::gamma;

collision::Bounds3 TriangleShape::object_bounds(const Geometry& t) {
    collision::Bounds3 b;  // vertices are exact: min/max of them is the exact box
    b.extend(t.a);
    b.extend(t.b);
    b.extend(t.c);
    return b;
}

ShapeLight TriangleShape::light(const Geometry& t, const Transform& xf, const std::vector<Mesh>&) {
    ShapeLight l;
    l.strategy = ShapeLight::Strategy::WorldArea;
    l.origin = transform_point(xf.to_world, t.a);
    l.edge_u = transform_point(xf.to_world, t.b) - l.origin;
    l.edge_v = transform_point(xf.to_world, t.c) - l.origin;
    l.normal = glm::normalize(xf.normal_to_world * glm::cross(t.b - t.a, t.c - t.a));
    l.area = 0.5f * glm::length(glm::cross(l.edge_u, l.edge_v));
    l.area_pdf = 1.0f / l.area;
    return l;
}


}  // namespace sweeptrace

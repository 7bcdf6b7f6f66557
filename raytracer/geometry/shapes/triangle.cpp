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

void TriangleShape::sample(const Geometry&, const ShapeLight& l, float, float u1, float u2, SurfacePoint& out) {
    const glm::vec2 b = uniform_triangle(u1, u2);
    // Barycentrics (b0, b1) of a and b: point = a + b1 (b - a) + (1 - b0 - b1) (c - a).
    out.point = l.origin + b.y * l.edge_u + (1.0f - b.x - b.y) * l.edge_v;
    out.normal = l.normal;
    out.error = gamma(4) * (glm::abs(l.origin) + glm::abs(l.edge_u) + glm::abs(l.edge_v));
}

}  // namespace sweeptrace

#pragma once
// The triangle's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_triangle.cpp.
#include <array>
#include <string_view>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/bounds3.hpp"
#include "collision/float_error.hpp"
#include "collision/shapes.hpp"
#include "raytracer/geometry/shapes/flat_front.hpp"
#include "raytracer/geometry/shapes/mesh_instance.hpp"
#include "raytracer/geometry/shapes/shape_home.hpp"

namespace sweeptrace {

struct TriangleShape {
    using Geometry = collision::Triangle;
    static constexpr std::string_view kType = "triangle";
    static constexpr std::array<std::string_view, 3> kKeys{"a", "b", "c"};
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader&);

    static collision::Bounds3 object_bounds(const Geometry& g);
    // WorldArea: uniform on the world triangle.
    static ShapeLight light(const Geometry& g, const Transform& xf, const std::vector<Mesh>& meshes);
    static void sample(const Geometry& g, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
    // uv of an object-space point p on the triangle: its barycentrics (b1, b2) of b and c, the coordinates of p - g.a in the edges
    // (g.b - g.a), (g.c - g.a) (dual basis through the normal n = (g.b - g.a) x (g.c - g.a): s = ((d x (g.c - g.a)) . n) / |n|^2, ...).
    static glm::vec2 uv(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 d = p - g.a, n = glm::cross((g.b - g.a), (g.c - g.a));
        const float nn = glm::dot(n, n);
        return {glm::dot(glm::cross(d, (g.c - g.a)), n) / nn, glm::dot(glm::cross((g.b - g.a), d), n) / nn};
    }
    static UvTangents uv_tangents(const Geometry& g, const glm::vec3&) { return {g.b - g.a, g.c - g.a}; }
    // Flat: a point of its plane and its front (emitting) normal, in object space, unnormalised.
    static FlatFront front(const Geometry& g) { return {g.a, glm::cross(g.b - g.a, g.c - g.a)}; }
};

template <class Node, class Loader>
TriangleShape::Geometry TriangleShape::read(const Node& node, Loader&) {
    const Geometry t{node.at("a").vec3(), node.at("b").vec3(), node.at("c").vec3()};
    if (scene_keys::parallel(glm::dvec3(t.b) - glm::dvec3(t.a), glm::dvec3(t.c) - glm::dvec3(t.a)))
        node.fail("a, b and c are collinear: the triangle has no area");
    return t;
}

// Inline: called once per light sample, through visit_shape.
inline void TriangleShape::sample(const Geometry&, const ShapeLight& l, float, float u1, float u2, SurfacePoint& out) {
    const glm::vec2 b = uniform_triangle(u1, u2);
    // Barycentrics (b0, b1) of a and b: point = a + b1 (b - a) + (1 - b0 - b1) (c - a).
    out.point = l.origin + b.y * l.edge_u + (1.0f - b.x - b.y) * l.edge_v;
    out.normal = l.normal;
    out.error = collision::gamma(4) * (glm::abs(l.origin) + glm::abs(l.edge_u) + glm::abs(l.edge_v));
}

}  // namespace sweeptrace

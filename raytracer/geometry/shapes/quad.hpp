#pragma once
// The quad's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_quad.cpp.
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

struct QuadShape {
    using Geometry = collision::Quad;
    static constexpr std::string_view kType = "quad";
    static constexpr std::array<std::string_view, 3> kKeys{"corner", "edge_u", "edge_v"};
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader&);

    static collision::Bounds3 object_bounds(const Geometry& g);
    // WorldArea: uniform on the world parallelogram.
    static ShapeLight light(const Geometry& g, const Transform& xf, const std::vector<Mesh>& meshes);
    static void sample(const Geometry& g, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
    // uv of an object-space point p on the plane: (s, t) in [0, 1]^2, the coordinates of p - g.corner in the edges
    // g.edge_u, g.edge_v (dual basis through the normal n = g.edge_u x g.edge_v: s = ((d x g.edge_v) . n) / |n|^2, ...).
    static glm::vec2 uv(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 d = p - g.corner, n = glm::cross(g.edge_u, g.edge_v);
        const float nn = glm::dot(n, n);
        return {glm::dot(glm::cross(d, g.edge_v), n) / nn, glm::dot(glm::cross(g.edge_u, d), n) / nn};
    }
    static UvTangents uv_tangents(const Geometry& g, const glm::vec3&) { return {g.edge_u, g.edge_v}; }
    // Flat: a point of its plane and its front (emitting) normal, in object space, unnormalised.
    static FlatFront front(const Geometry& g) { return {g.corner, glm::cross(g.edge_u, g.edge_v)}; }
};

template <class Node, class Loader>
QuadShape::Geometry QuadShape::read(const Node& node, Loader&) {
    const Geometry q{node.at("corner").vec3(), node.at("edge_u").vec3(), node.at("edge_v").vec3()};
    if (scene_keys::parallel(q.edge_u, q.edge_v))
        node.fail("edge_u and edge_v must not be parallel (or zero): the quad has no area");
    return q;
}

// Inline: called once per light sample, through visit_shape.
inline void QuadShape::sample(const Geometry&, const ShapeLight& l, float, float u1, float u2, SurfacePoint& out) {
    out.point = l.origin + u1 * l.edge_u + u2 * l.edge_v;
    out.normal = l.normal;
    out.error = collision::gamma(3) * (glm::abs(l.origin) + glm::abs(l.edge_u) + glm::abs(l.edge_v));
}

}  // namespace sweeptrace

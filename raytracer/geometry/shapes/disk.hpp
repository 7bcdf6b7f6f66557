#pragma once
// The disk's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_disk.cpp.
#include <array>
#include <cmath>
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

struct DiskShape {
    using Geometry = collision::Disk;
    static constexpr std::string_view kType = "disk";
    static constexpr std::array<std::string_view, 3> kKeys{"center", "normal", "radius"};
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader&);

    static collision::Bounds3 object_bounds(const Geometry& g);
    // WorldArea: the unit disk's image is an ellipse c + x U + y V, U and V the images of two orthogonal radii; uniform on the disk stays uniform on the ellipse.
    static ShapeLight light(const Geometry& g, const Transform& xf, const std::vector<Mesh>& meshes);
    static void sample(const Geometry& g, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
    // uv of an object-space point p on the disk: u = the angle about the normal / 2 pi in [0, 1),
    // measured from the tangent s of geometry/warps.hpp's Frame(normal) toward its t; v = the
    // distance from the centre / radius.
    static glm::vec2 uv(const Geometry& g, const glm::vec3& p) {
        const Frame f(glm::normalize(g.normal));
        const glm::vec3 d = p - g.center;
        const float x = glm::dot(d, f.s), y = glm::dot(d, f.t);
        const float a = std::atan2(y, x) / (2.0f * kPi);
        return {a < 0.0f ? a + 1.0f : a, std::sqrt(x * x + y * y) / g.radius};
    }
    // Around the centre (from s toward t) and outward; zero at the centre.
    static UvTangents uv_tangents(const Geometry& g, const glm::vec3& p) {
        const Frame f(glm::normalize(g.normal));
        const glm::vec3 d = p - g.center;
        const float x = glm::dot(d, f.s), y = glm::dot(d, f.t), r = std::sqrt(x * x + y * y);
        if (!(r > 0.0f)) return {};
        return {2.0f * kPi * (x * f.t - y * f.s), (g.radius / r) * (x * f.s + y * f.t)};
    }
    // Flat: a point of its plane and its front (emitting) normal, in object space, unnormalised.
    static FlatFront front(const Geometry& g) { return {g.center, g.normal}; }
};

template <class Node, class Loader>
DiskShape::Geometry DiskShape::read(const Node& node, Loader&) {
    glm::vec3 normal(0.0f, 1.0f, 0.0f);
    if (auto n = node.find("normal")) normal = glm::vec3(glm::normalize(glm::dvec3(n->nonzero_vec3())));
    return {scene_keys::center_or_origin(node), normal, node.at("radius").number_at_least(0.0f, false)};
}

// Inline: called once per light sample, through visit_shape.
inline void DiskShape::sample(const Geometry&, const ShapeLight& l, float, float u1, float u2, SurfacePoint& out) {
    const glm::vec2 c = concentric_disk(u1, u2);
    out.point = l.origin + c.x * l.edge_u + c.y * l.edge_v;
    out.normal = l.normal;
    out.error = collision::gamma(3) * (glm::abs(l.origin) + glm::abs(l.edge_u) + glm::abs(l.edge_v));
}

}  // namespace sweeptrace

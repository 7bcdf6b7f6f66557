#pragma once
// The sphere's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_sphere.cpp.
#include "raytracer/geometry/shapes/mesh_instance.hpp"
#include "raytracer/geometry/shapes/shape_home.hpp"

namespace sweeptrace {

struct SphereShape {
    using Geometry = collision::Sphere;
    static constexpr std::string_view kType = "sphere";
    static constexpr std::array<std::string_view, 2> kKeys{"center", "radius"};
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader&) {
        return {scene_keys::center_or_origin(node), node.at("radius").number_at_least(0.0f, false)};
    }

    static collision::Bounds3 object_bounds(const Geometry& s);
    // Under a similarity (uniform scale, rotation, translation): SphereCone, else ObjectArea.
    static ShapeLight light(const Geometry& s, const Transform& xf, const std::vector<Mesh>& meshes);
    // SphereCone: uniform by area on the world sphere; ObjectArea: on the object sphere.
    static void sample(const Geometry& s, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
};

// Inline: called once per light sample, through visit_shape.
inline void SphereShape::sample(const Geometry& s, const ShapeLight& l, float, float u1, float u2, SurfacePoint& out) {
    out.normal = uniform_sphere(u1, u2);
    if (l.strategy == ShapeLight::Strategy::SphereCone) {
        out.point = l.origin + l.radius * out.normal;
        out.error = collision::gamma(5) * (glm::abs(l.origin) + glm::vec3(l.radius));
    } else {
        out.point = s.center + s.radius * out.normal;
        out.error = collision::gamma(3) * (glm::abs(s.center) + glm::vec3(s.radius));
    }
}

}  // namespace sweeptrace

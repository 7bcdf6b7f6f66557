#pragma once
// The cylinder's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_cylinder.cpp.
#include "raytracer/geometry/shapes/mesh_instance.hpp"
#include "raytracer/geometry/shapes/shape_home.hpp"

namespace sweeptrace {

struct CylinderShape {
    using Geometry = collision::Cylinder;
    static constexpr std::string_view kType = "cylinder";
    static constexpr std::array<std::string_view, 3> kKeys{"center", "radius", "height"};
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader&);

    static collision::Bounds3 object_bounds(const Geometry& g);
    // ObjectArea: side or a cap chosen by area, then uniform on it.
    static ShapeLight light(const Geometry& g, const Transform& xf, const std::vector<Mesh>& meshes);
    static void sample(const Geometry& g, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
};

template <class Node, class Loader>
CylinderShape::Geometry CylinderShape::read(const Node& node, Loader&) {
    return {scene_keys::center_or_origin(node), node.at("radius").number_at_least(0.0f, false),
            node.at("height").number_at_least(0.0f, false)};
}

}  // namespace sweeptrace

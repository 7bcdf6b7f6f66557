#pragma once
// The cylinder's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_cylinder.cpp.
#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/bounds3.hpp"
#include "collision/shapes.hpp"
#include "raytracer/geometry/shapes/mesh_instance.hpp"
#include "raytracer/geometry/shapes/scene_keys.hpp"
#include "raytracer/geometry/shapes/shape_light.hpp"
#include "raytracer/geometry/shapes/uv_maps.hpp"
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
    // uv of an object-space point p on the cylinder: u = longitude about its axis, atan2(z, x)
    // / 2 pi from +X toward +Z; v = height from the bottom cap / height, in [0, 1] on the side
    // (the caps take their rim's v: 0 below, 1 on top, so a texture on them is constant
    // radially).
    static glm::vec2 uv(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 d = p - g.center;
        return {uv_maps::longitude(d.x, d.z), std::clamp(d.y / g.height + 0.5f, 0.0f, 1.0f)};
    }
    // Around the axis, and up it (on the caps, where v is constant, dpdv lies along the normal).
    static UvTangents uv_tangents(const Geometry& g, const glm::vec3& p) {
        return {uv_maps::longitude_tangent(p - g.center), glm::vec3(0.0f, g.height, 0.0f)};
    }
};

template <class Node, class Loader>
CylinderShape::Geometry CylinderShape::read(const Node& node, Loader&) {
    return {scene_keys::center_or_origin(node), node.at("radius").number_at_least(0.0f, false),
            node.at("height").number_at_least(0.0f, false)};
}

}  // namespace sweeptrace

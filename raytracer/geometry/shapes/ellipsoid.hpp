#pragma once
// The ellipsoid's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_ellipsoid.cpp.
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

struct EllipsoidShape {
    using Geometry = collision::Ellipsoid;
    static constexpr std::string_view kType = "ellipsoid";
    static constexpr std::array<std::string_view, 2> kKeys{"center", "radii"};
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader&);

    static collision::Bounds3 object_bounds(const Geometry& g);
    // ObjectArea, as the unit sphere under L diag(radii) translated to the centre.
    static ShapeLight light(const Geometry& g, const Transform& xf, const std::vector<Mesh>& meshes);
    static void sample(const Geometry& g, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
    // uv of an object-space point p on the ellipsoid: the sphere's (longitude, polar angle from
    // +Y) of (p - center) / radii, the point's direction on the unit sphere it is stretched from.
    static glm::vec2 uv(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 d = glm::normalize((p - g.center) / g.radii);
        return {uv_maps::longitude(d.x, d.z), uv_maps::polar(d.y)};
    }
    // The unit sphere's derivatives at (p - center) / radii, scaled back by the radii.
    static UvTangents uv_tangents(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 d = glm::normalize((p - g.center) / g.radii);
        return {g.radii * uv_maps::longitude_tangent(d), g.radii * uv_maps::polar_tangent(d)};
    }
};

template <class Node, class Loader>
EllipsoidShape::Geometry EllipsoidShape::read(const Node& node, Loader&) {
    return {scene_keys::center_or_origin(node), scene_keys::positive_vec3(node.at("radii"))};
}

}  // namespace sweeptrace

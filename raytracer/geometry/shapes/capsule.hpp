#pragma once
// The capsule's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_capsule.cpp.
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

struct CapsuleShape {
    using Geometry = collision::Capsule;
    static constexpr std::string_view kType = "capsule";
    static constexpr std::array<std::string_view, 3> kKeys{"center", "radius", "height"};
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader&);

    static collision::Bounds3 object_bounds(const Geometry& g);
    // ObjectArea: side or the two hemispheres chosen by area, then uniform.
    static ShapeLight light(const Geometry& g, const Transform& xf, const std::vector<Mesh>& meshes);
    static void sample(const Geometry& g, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
    // uv of an object-space point p on the capsule: u = longitude about its axis, atan2(z, x)
    // / 2 pi from +X toward +Z; v = height above its lowest point / its whole length
    // (height + 2 radius), 0 at the bottom pole, 1 at the top.
    static glm::vec2 uv(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 d = p - g.center;
        const float length = g.height + 2.0f * g.radius;
        return {uv_maps::longitude(d.x, d.z), std::clamp(d.y / length + 0.5f, 0.0f, 1.0f)};
    }
    // Around the axis, and up it (v grows with height alone; the frame keeps dpdv's tangential part).
    static UvTangents uv_tangents(const Geometry& g, const glm::vec3& p) {
        return {uv_maps::longitude_tangent(p - g.center), glm::vec3(0.0f, g.height + 2.0f * g.radius, 0.0f)};
    }
};

template <class Node, class Loader>
CapsuleShape::Geometry CapsuleShape::read(const Node& node, Loader&) {
    // height 0 is a sphere: allowed, the hemispheres alone close it.
    return {scene_keys::center_or_origin(node), node.at("radius").number_at_least(0.0f, false),
            node.at("height").number_at_least(0.0f, true)};
}

}  // namespace sweeptrace

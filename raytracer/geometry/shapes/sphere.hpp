#pragma once
// The sphere's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_sphere.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/bounds3.hpp"
#include "collision/float_error.hpp"
#include "collision/shapes.hpp"
#include "raytracer/geometry/shapes/mesh_instance.hpp"
#include "raytracer/geometry/shapes/scene_keys.hpp"
#include "raytracer/geometry/shapes/shape_light.hpp"
#include "raytracer/geometry/shapes/uv_maps.hpp"
#include "raytracer/geometry/warps.hpp"
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
    // uv of an object-space point p on the sphere, from its direction d from the centre:
    // (phi / 2 pi, theta / pi) with phi = atan2(d.z, d.x) in [0, 2 pi) and theta = acos(d.y) from
    // +Y (the convention of collision's sphere hit uv).
    static glm::vec2 uv(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 d = glm::normalize(p - g.center);
        return {uv_maps::longitude(d.x, d.z), uv_maps::polar(d.y)};
    }
    // d(point)/du, d(point)/dv of that map (u around +Y, v down the meridian; zero at the poles).
    static UvTangents uv_tangents(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 d = p - g.center;
        return {uv_maps::longitude_tangent(d), uv_maps::polar_tangent(d)};
    }
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

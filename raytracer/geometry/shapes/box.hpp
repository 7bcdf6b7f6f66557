#pragma once
// The box's home in the renderer: scene keys, object-space bounds, light sampling.
// Intersection: collision/intersect_aabb.cpp.
#include <algorithm>
#include <array>
#include <string>

#include <glm/geometric.hpp>

#include "collision/bounds3.hpp"
#include "collision/shapes.hpp"
#include "raytracer/geometry/shapes/mesh_instance.hpp"
#include "raytracer/geometry/shapes/scene_keys.hpp"
#include "raytracer/geometry/shapes/shape_light.hpp"
#include "raytracer/geometry/shapes/uv_maps.hpp"
#include "raytracer/geometry/shapes/shape_home.hpp"

namespace sweeptrace {

struct BoxShape {
    using Geometry = collision::Aabb;
    static constexpr std::string_view kType = "box";
    static constexpr std::array<std::string_view, 4> kKeys{"center", "size", "min", "max"};
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader&);

    static collision::Bounds3 object_bounds(const Geometry& g);
    // ObjectArea: a face chosen by area, then uniform on it.
    static ShapeLight light(const Geometry& g, const Transform& xf, const std::vector<Mesh>& meshes);
    static void sample(const Geometry& g, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
    // uv of an object-space point p on the box: each face is mapped whole onto [0, 1]^2. The face
    // is the axis k where |p - center| / size is largest; (u, v) are the other two coordinates,
    // in the order (y, z) for an x face, (x, z) for a y face, (x, y) for a z face, each from the
    // box's low side (0) to its high side (1).
    static glm::vec2 uv(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 f = (p - g.center) / g.size;  // in [-1/2, 1/2] per axis
        const glm::vec3 a = glm::abs(f);
        const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        const int i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
        return {std::clamp(f[i] + 0.5f, 0.0f, 1.0f), std::clamp(f[j] + 0.5f, 0.0f, 1.0f)};
    }
    // Along the face's two axes (the same face choice as uv), each the box's size along it.
    static UvTangents uv_tangents(const Geometry& g, const glm::vec3& p) {
        const glm::vec3 a = glm::abs((p - g.center) / g.size);
        const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        const int i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
        UvTangents t;
        t.dpdu[i] = g.size[i];
        t.dpdv[j] = g.size[j];
        return t;
    }
};

template <class Node, class Loader>
BoxShape::Geometry BoxShape::read(const Node& node, Loader&) {
    const bool by_center = node.has("center") || node.has("size");
    const bool by_bounds = node.has("min") || node.has("max");
    if (by_center == by_bounds) node.fail("give either \"center\" and \"size\", or \"min\" and \"max\"");
    Geometry box;
    if (by_center) {
        box.center = scene_keys::center_or_origin(node);
        box.size = scene_keys::positive_vec3(node.at("size"));
    } else {
        const auto min = node.at("min");
        const glm::vec3 lo = min.vec3();
        const auto max = node.at("max");
        const glm::vec3 hi = max.vec3();
        for (int k = 0; k < 3; ++k)
            if (!(hi[k] > lo[k]))
                max.element(static_cast<std::size_t>(k))
                    .fail("must be > min[" + std::to_string(k) + "] (" +
                          min.element(static_cast<std::size_t>(k)).shown() + ")");
        box.center = collision::Bounds3{lo, hi}.center();  // overflow-safe midpoint
        box.size = hi - lo;
    }
    return box;
}

}  // namespace sweeptrace

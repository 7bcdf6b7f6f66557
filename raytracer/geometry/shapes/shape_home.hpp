#pragma once
// What a shape's home (geometry/shapes/<shape>.hpp) provides, stated once and checked for every
// shape in the table (geometry/shape.hpp static_asserts it):
//   Geometry        the collision struct (collision/shapes.hpp) or MeshInstance
//   kType, kKeys    its type name in scene files and the keys it reads besides the common ones
//                   (type, material, transform, name)
//   read(node, loader)   its keys, validated, from the scene loader's JSON node (a template, so
//                   the home does not depend on the loader; errors name the JSON path)
//   object_bounds(g)     its box in object space, every bound rounded outward
//   light(g, xf, meshes) which LightSet strategy samples it as a light (shape_light.hpp), with
//                   that strategy's precomputed data and the area its selection weight uses
//   sample(g, light, u_part, u1, u2, out)   a uniform point on its surface, with its rounding
//                   bound and normal, in the space the strategy names
//   uv(g, object_point)  its documented texture parameterisation, computed only for hits whose
//                   material reads a texture (a mesh instance: mesh_uv, from the triangle's vt)
//   uv_tangents(g, object_point)  with uv: d(point)/du and d(point)/dv there, for normal maps
//                   (a mesh instance: mesh_uv_tangents, per triangle)
//   front(g)        flat shapes only: a point and the front normal (the emitter-facing warning)
// Also the includes every home needs, so a home's header is its own code.
#include <array>
#include <concepts>
#include <string_view>
#include <vector>

#include "collision/bounds3.hpp"
#include "collision/float_error.hpp"
#include "collision/shapes.hpp"
#include "raytracer/geometry/shapes/scene_keys.hpp"
#include "raytracer/geometry/shapes/shape_light.hpp"
#include "raytracer/geometry/shapes/uv_maps.hpp"
#include "raytracer/geometry/transform.hpp"
#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

struct Mesh;  // shapes/mesh_instance.hpp

template <class H>
concept ShapeHome = requires(const typename H::Geometry& g, const Transform& xf, const std::vector<Mesh>& meshes,
                             const ShapeLight& light, SurfacePoint& out) {
    { H::kType } -> std::convertible_to<std::string_view>;
    { H::kKeys.size() } -> std::convertible_to<std::size_t>;
    { H::object_bounds(g) } -> std::same_as<collision::Bounds3>;
    { H::light(g, xf, meshes) } -> std::same_as<ShapeLight>;
    { H::sample(g, light, 0.0f, 0.0f, 0.0f, out) } -> std::same_as<void>;
};

}  // namespace sweeptrace

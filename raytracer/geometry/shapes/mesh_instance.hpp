#pragma once
// A triangle mesh and its instances: the mesh's home in the renderer (scene keys, light
// sampling). A mesh is shared by every object that instances it (two-level acceleration: a
// transformed mesh is not copied); its bounds come from its own bottom-level BVH (accel/), and
// its triangles are intersected by collision/intersect_triangle.cpp.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "collision/bounds3.hpp"
#include "collision/mesh.hpp"
#include "raytracer/geometry/shapes/shape_home.hpp"

namespace sweeptrace {

struct Mesh {
    collision::TriangleMesh triangles;
    std::vector<glm::vec3> vertex_normals;  // empty, or one per vertex (smooth shading)
    std::vector<glm::vec2> vertex_uvs;      // empty, or one per vertex (OBJ vt), for textures
    std::string source;                     // file it came from, for messages
};

struct MeshInstance {
    std::uint32_t mesh = 0;  // index into the scene's meshes
};

struct MeshInstanceShape {
    using Geometry = MeshInstance;
    static constexpr std::string_view kType = "mesh";
    // "materials": "from_obj" (the default without a "material"): the OBJ's own (scene/obj_materials.hpp).
    // Instead of "file", the mesh itself: "vertices", "indices", "normals", "uvs" (scene/inline_mesh.hpp).
    static constexpr std::array<std::string_view, 6> kKeys{"file", "materials", "vertices", "indices", "normals", "uvs"};
    // The loader resolves and loads the file (scene/), once however many objects instance it, or
    // reads the inline mesh.
    template <class Node, class Loader>
    static Geometry read(const Node& node, Loader& loader) {
        return {loader.mesh_index(node)};
    }

    // Not analytic: empty. The acceleration structures box a mesh by its own BVH.
    static collision::Bounds3 object_bounds(const Geometry&) { return {}; }
    // MeshArea: a triangle chosen by world area, then uniformly on it (uniform over the surface).
    static ShapeLight light(const Geometry& m, const Transform& xf, const std::vector<Mesh>& meshes);
    static void sample(const Geometry& m, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out);
    // uv of object-space point p on triangle `primitive`: the OBJ's vt interpolated by p's
    // barycentrics on that triangle; (0, 0) when the mesh has none (the loader refuses textures
    // on such meshes). Not the uv(geometry, point) of the analytic homes: a mesh point needs its
    // triangle.
    static glm::vec2 mesh_uv(const Geometry& m, const std::vector<Mesh>& meshes, std::uint32_t primitive,
                             const glm::vec3& p);
    // d(point)/du, d(point)/dv on triangle `primitive` from its corners' positions and vt (one
    // pair per triangle, as the uv is linear on it); zero when its uv triangle is degenerate.
    static UvTangents mesh_uv_tangents(const Geometry& m, const std::vector<Mesh>& meshes, std::uint32_t primitive);
};

}  // namespace sweeptrace

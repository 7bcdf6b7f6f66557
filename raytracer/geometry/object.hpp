#pragma once
// A scene object: one collision shape (or a mesh instance) in its own object space, an affine
// transform to world space and a material. Analytic shapes stay analytic.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "collision/mesh.hpp"
#include "collision/shapes.hpp"
#include "raytracer/geometry/transform.hpp"

namespace sweeptrace {

// A triangle mesh shared by every object that instances it (two-level acceleration: a
// transformed mesh is not copied).
struct Mesh {
    collision::TriangleMesh triangles;
    std::vector<glm::vec3> vertex_normals;  // empty, or one per vertex (smooth shading)
    std::string source;                     // file it came from, for messages
};

struct MeshInstance {
    std::uint32_t mesh = 0;  // index into Scene::meshes
};

using Shape = std::variant<collision::Sphere, collision::Aabb, collision::Cylinder, collision::Capsule,
                           collision::Ellipsoid, collision::Disk, collision::Quad, collision::Triangle,
                           MeshInstance>;

struct Object {
    Shape shape;
    Transform transform;
    std::uint32_t material = 0;  // index into Scene::materials
    std::string name;            // for messages and statistics
};

}  // namespace sweeptrace

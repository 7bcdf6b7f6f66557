#pragma once
// The thesis's shapes as plain structs. Sizes follow the thesis: Aabb, Cylinder and Capsule store
// centre and *full* extents (width, height, depth / full height), as its Box and Cylinder did.
#include <glm/vec3.hpp>

namespace collision {

struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};

// Axis-aligned box: centre and full size (the thesis's Box{pos, dims}).
struct Aabb {
    glm::vec3 center{0.0f};
    glm::vec3 size{1.0f};
    glm::vec3 min() const { return center - 0.5f * size; }
    glm::vec3 max() const { return center + 0.5f * size; }
};

// Y-aligned cylinder, closed by two flat caps; height is the full height.
struct Cylinder {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    float height = 1.0f;
};

// Y-aligned capsule: the cylinder part has full height `height`, closed by two hemispheres
// of the same radius (total extent height + 2 radius), as the thesis's "bean".
struct Capsule {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    float height = 1.0f;
};

// Capsule of any orientation: the set of points within `radius` of segment a-b.
struct OrientedCapsule {
    glm::vec3 a{0.0f};
    glm::vec3 b{0.0f, 1.0f, 0.0f};
    float radius = 1.0f;
};

// Axis-aligned ellipsoid: centre and semi-axes (the thesis scales by 1/dims).
struct Ellipsoid {
    glm::vec3 center{0.0f};
    glm::vec3 radii{1.0f};
};

// Infinite plane through `point` with unit normal `normal`.
struct Plane {
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
};

// Flat disk: centre, unit normal, radius. Two-sided.
struct Disk {
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    float radius = 1.0f;
};

// Parallelogram corner + s*edge_u + t*edge_v, s,t in [0,1]; normal = normalize(edge_u x edge_v).
// Not in the thesis; a renderer needs it for walls and area lights, kept analytic.
struct Quad {
    glm::vec3 corner{0.0f};
    glm::vec3 edge_u{1.0f, 0.0f, 0.0f};
    glm::vec3 edge_v{0.0f, 0.0f, 1.0f};
};

// Triangle a, b, c; front face is counter-clockwise: normal = (b - a) x (c - a).
struct Triangle {
    glm::vec3 a{0.0f};
    glm::vec3 b{1.0f, 0.0f, 0.0f};
    glm::vec3 c{0.0f, 1.0f, 0.0f};
};

// A line (result of plane-plane): point + s * direction.
struct Line {
    glm::vec3 point{0.0f};
    glm::vec3 direction{1.0f, 0.0f, 0.0f};
};

}  // namespace collision

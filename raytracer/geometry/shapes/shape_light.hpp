#pragma once
// What a shape's home (geometry/shapes/<shape>.hpp) tells the renderer's light sampler about one
// emissive object of that shape, and the surface point it samples. LightSet (render/lights/lights.hpp)
// owns the strategies and the densities; each home owns only its own geometry: which strategy
// fits it, its area, and how a uniform point on its surface is drawn.
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "collision/mesh.hpp"
#include "raytracer/geometry/transform.hpp"

namespace sweeptrace {

struct ShapeLight {
    enum class Strategy : std::uint8_t {
        // Sphere under a similarity: the cone of directions it subtends from the shading point
        // (LightSet); from inside or on it, the home's world-space area sample.
        SphereCone,
        // The home samples world points uniformly by world area (flat shapes: an affine map keeps
        // them flat, with constant area scaling).
        WorldArea,
        // The home samples object-space points uniformly by object area; they are mapped by
        // `to_world` and the world density follows Nanson's formula (lights.cpp).
        ObjectArea,
        // The home samples object-space points uniformly over the *world* area (a mesh: a
        // triangle chosen by world area); mapped by `to_world`, density 1 / area.
        MeshArea,
    };
    Strategy strategy = Strategy::WorldArea;
    // Selection weight's area: the world area, or, for shapes whose world area has no closed form
    // (non-uniformly scaled curved shapes), object_area_stand_in(). Any positive weight is unbiased.
    float area = 0.0f;
    float area_pdf = 0.0f;  // ObjectArea: the object-space density; the others: 1 / world area

    // World-space kinds: origin + edges (parallelogram, triangle, ellipse), or centre + radius.
    glm::vec3 origin{0.0f}, edge_u{0.0f}, edge_v{0.0f};
    float radius = 0.0f;
    glm::vec3 normal{0.0f};  // flat kinds: world front normal

    // Object-space kinds: the map of sampled points (with the ellipsoid's radii folded in).
    glm::mat4 to_world{1.0f};
    glm::mat3 linear{1.0f};
    glm::mat3 normal_to_world{1.0f};
    float inv_abs_det = 1.0f;

    // MeshArea: the mesh and its cumulative world triangle areas.
    const collision::TriangleMesh* mesh = nullptr;
    std::vector<float> triangle_cdf;
};

// A point drawn on a shape's surface, in the space its strategy names, with its rounding bound
// and unit (object kinds: not yet normalised after mapping) outward normal.
struct SurfacePoint {
    glm::vec3 point{0.0f};
    glm::vec3 error{0.0f};
    glm::vec3 normal{0.0f};
    std::uint32_t primitive = 0;  // MeshArea: the triangle (an emission texture reads its uv)
};

// The object-space strategies' starting point: the object's own transform.
inline ShapeLight object_space_light(const Transform& xf, ShapeLight::Strategy strategy) {
    ShapeLight l;
    l.strategy = strategy;
    l.to_world = xf.to_world;
    l.linear = glm::mat3(xf.to_world);
    l.normal_to_world = xf.normal_to_world;
    l.inv_abs_det = 1.0f / std::abs(glm::determinant(l.linear));
    return l;
}

// Stand-in world area of a curved shape of object area `object_area` under a linear map with
// 1 / |det| = inv_abs_det: the area scale of a uniform scale with the same volume change.
inline float object_area_stand_in(float object_area, float inv_abs_det) {
    return object_area * std::cbrt(1.0f / (inv_abs_det * inv_abs_det));
}

}  // namespace sweeptrace

namespace sweeptrace {

// m (p, 1) as GLM evaluates it: where a light's world frame is set up once (flat lights' corners
// and edges, a sphere's centre). Their sampling bounds are relative to those world values.
inline glm::vec3 transform_point(const glm::mat4& m, const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

}  // namespace sweeptrace

#pragma once
// The ray families of the accuracy harness: seeded, reproducible (shape, ray) cases for every
// ray-shape routine of collision/, each family aimed at one way an intersector can fail.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "collision/mesh.hpp"
#include "collision/ray.hpp"
#include "collision/shapes.hpp"
#include "raytracer/geometry/shape.hpp"

namespace sweeptrace::accuracy {

enum class Family {
    Uniform,     // scale 1 shapes, rays from 3..6 extents away aimed inside the bounding sphere
    Grazing,     // tangent to the surface at a random point, origin moved -4..+4 ulps off it
    Far,         // ray origin 1e0 .. 1e6 (log-uniform) extents away from a unit shape
    Huge,        // shape of size 1e5 centred up to 1e5 from the world origin
    Tiny,        // shape of size 1e-4 centred up to 1 from the world origin, seen from ~1 away
    SurfaceOut,  // secondary rays leaving a hit point away from the shape (scales 1e-4 .. 1e5)
    SurfaceIn,   // secondary rays leaving a hit point into the shape / through a flat one
    Parallel,    // rays parallel to faces, caps, axes and planes, in and next to their planes
    Edges,       // rays from inside a closed shape or mesh through its vertices and edges
};

inline constexpr Family all_families[] = {Family::Uniform,    Family::Grazing,   Family::Far,
                                          Family::Huge,       Family::Tiny,      Family::SurfaceOut,
                                          Family::SurfaceIn,  Family::Parallel,  Family::Edges};

const char* family_name(Family f);

using CaseRng = std::mt19937_64;

template <class Shape>
struct Case {
    Shape shape;
    collision::Ray ray;
    glm::vec3 secondary_dir{0.0f};  // Surface families: unit direction, side chosen at spawn
};

// A closed surface made of faces (an icosphere of triangles, a cube of quads) and rays from
// inside it, each aimed exactly at one of its vertices or (within rounding) at a point of an edge.
template <class Face>
struct ClosedMeshCase {
    std::vector<Face> faces;
    std::vector<collision::Ray> rays;
};

// Does the family apply to the shape? (Parallel has nothing to be parallel to on a sphere;
// Edges needs edges.)
template <class Shape>
bool family_applies(Family f);

// Cases for every family except Edges on Triangle / Quad, which use make_closed_meshes.
template <class Shape>
std::vector<Case<Shape>> make_cases(Family f, std::size_t n, std::uint64_t seed);

// Closed meshes with `rays_per_mesh` rays each, about n rays in total.
template <class Face>
std::vector<ClosedMeshCase<Face>> make_closed_meshes(std::size_t n, std::uint64_t seed);

// A watertight icosphere: 20 * 4^level triangles of radius `radius` around `center`, vertices
// rounded to float once and shared, counter-clockwise seen from outside.
std::vector<collision::Triangle> icosphere(int level, const glm::vec3& center, float radius,
                                           std::vector<glm::vec3>* vertices = nullptr);

// The same icosphere as an indexed mesh (vertices shared by index).
collision::TriangleMesh icosphere_mesh(int level, const glm::vec3& center, float radius);

template <class Shape>
bool shape_is_closed();

// A shape's name in tables and on the command line: a scene shape's type name from its home
// (geometry/shapes/), so the harness and scene files agree; the two collision-only shapes
// (plane, oriented capsule) name themselves in cases.cpp.
template <class Shape>
const char* shape_name() {
    return Shapes::HomeOf<Shape>::kType.data();
}
template <>
const char* shape_name<collision::Plane>();
template <>
const char* shape_name<collision::OrientedCapsule>();

// A uniformly distributed unit vector.
glm::vec3 unit_vector(CaseRng& rng);

// pbrt's origin offset for a secondary ray: move `p` along the normal by the projection of its
// error bound, toward the side `dir` points to, then one float further away in each component.
glm::vec3 offset_origin(const glm::vec3& p, const glm::vec3& error, const glm::vec3& normal, const glm::vec3& dir);

}  // namespace sweeptrace::accuracy

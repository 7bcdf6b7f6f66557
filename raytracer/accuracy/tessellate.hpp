#pragma once
// Analytic shapes as triangle meshes, for "model no more than a scene needs": the same object
// rendered analytic and tessellated. Every vertex lies on the analytic surface (the mesh is
// inscribed), vertex normals are the analytic normals there (smooth shading), and the mesh is
// closed: caps and poles share their rim and pole vertices with the sides.
#include <cstddef>

#include "collision/shapes.hpp"
#include "raytracer/geometry/object.hpp"

namespace sweeptrace::accuracy {

// About `triangles` triangles (the exact count depends on the grid the shape allows).
Mesh tessellate(const collision::Sphere& s, std::size_t triangles);
Mesh tessellate(const collision::Ellipsoid& e, std::size_t triangles);
Mesh tessellate(const collision::Cylinder& c, std::size_t triangles);
Mesh tessellate(const collision::Capsule& c, std::size_t triangles);

}  // namespace sweeptrace::accuracy

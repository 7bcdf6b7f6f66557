#pragma once
// A mesh object given in the scene itself, not in a file (scenes/README.md, "mesh"): flat arrays
// "vertices" [x0, y0, z0, x1, ...], "indices" [a0, b0, c0, a1, ...] (triangles, counter-clockwise
// seen from their front, numbered from 0), and optionally "normals" (one per vertex, made unit)
// and "uvs" [u0, v0, u1, ...] (one pair per vertex). It becomes a Mesh like a file's, with its
// own bottom-level BVH, so a converted scene keeps a pbrt trianglemesh's shading normals and uv
// and costs a few bytes per triangle, not an object each.
//
// Every complaint names the JSON path of the offending number: a count that is not a multiple of
// 3 (2 for uvs), an index out of range, a normal of zero length, a number not finite in float.
#include "raytracer/geometry/object.hpp"
#include "raytracer/scene/json_reader.hpp"

namespace sweeptrace {

// The object's keys besides "file": the mesh shape's home lists them.
inline constexpr std::string_view kInlineMeshKeys[] = {"vertices", "indices", "normals", "uvs"};

Mesh read_inline_mesh(const scene_json::Node& object);

}  // namespace sweeptrace

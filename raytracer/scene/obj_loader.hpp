#pragma once
// Wavefront OBJ → Mesh, through tinyobjloader, with the checks tinyobjloader leaves to its caller.
#include <filesystem>

#include "raytracer/geometry/object.hpp"
#include "raytracer/scene/obj_outline.hpp"

namespace sweeptrace {

// Loads the triangles of every group/object in `file`; polygons are split into fans (exact for
// the convex polygons OBJ exporters write). Vertex normals are kept when every face corner has
// one (and each is finite and non-zero); a vertex used with several normals is duplicated, at
// bit-identical position, so the mesh stays watertight. Otherwise `vertex_normals` is empty and
// the renderer shades with face normals. Texture coordinates (vt) likewise: kept in `vertex_uvs`
// when every face corner has one (finite), a vertex used with several duplicated; otherwise
// empty. Only vertices used by a face are kept.
//
// Throws InputError "<file>: ..." when the file cannot be read or is over kMaxMeshFileBytes,
// tinyobjloader reports an error, a face refers to a vertex, normal or texture coordinate that does not exist (with
// the face's line), a face has fewer than 3 or more than 255 corners, a vertex coordinate is
// missing, not a decimal number or not finite (with its line), or there are no faces at all.
// Lines may end in \n, \r\n or \r (obj_outline.hpp); the result does not depend on which.
// A name ending in .gz is inflated first, bounded by kMaxMeshFileBytes decompressed (gzip_file.hpp,
// whose errors it throws).
// With `outline`, the file's outline is also handed back (its faces in the order their triangles
// are stored, and its mtllib / usemtl statements: scene/obj_materials.hpp).
Mesh load_obj(const std::filesystem::path& file, ObjOutline* outline = nullptr);

}  // namespace sweeptrace

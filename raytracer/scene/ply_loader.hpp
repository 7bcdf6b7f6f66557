#pragma once
// Stanford PLY -> Mesh: ASCII, binary little-endian and binary big-endian, by a reader of our own.
//
// Why not assimp (Debian 12's libassimp-dev 5.2.5, which reads PLY among ~40 formats): it would
// add a large library (libassimp5 installs 9.8 MB and pulls in libdraco and libminizip, per
// `apt-cache show`) to read the one format we need; it reads the whole file into its own scene graph with no limit we can set on the counts a
// header declares; its errors are one generic string without the byte or line where the file is
// wrong; and it guesses the format from the content, so a fuzzer's bytes would reach dozens of
// parsers none of our tests cover. PLY itself is small (a text header, then fixed-size records);
// a reader of ~300 lines checks every count against the bytes that follow before it allocates,
// names the byte (binary) or line (ASCII) of every error, and is fuzzed (tests/fuzz/fuzz_ply.cpp).
//
// Read: element "vertex" with float/double/integer properties x, y, z (required), nx, ny, nz
// (optional, all three), and a uv pair u/v, s/t, texture_u/texture_v or texture_s/texture_t
// (optional); element "face" with a list property vertex_indices (or vertex_index) of 3 to 255
// corners: triangles as they are, quads and larger polygons split into fans from their first
// corner (exact for the convex polygons exporters write, as the OBJ loader does). Other elements
// and properties are skipped (their bytes still checked). Vertex normals are kept when every
// vertex has a finite, non-zero one (made unit); otherwise the mesh shades with face normals.
// Only vertices used by a face are kept, in order of first use.
//
// Throws InputError "<file>: <where>: <what>" (where: "header line N", "line N" in ASCII data,
// "byte N" in binary data) when the file cannot be read or is over kMaxMeshFileBytes, the header
// is malformed or uses a format or type PLY does not define, an element declares more records
// than the bytes after the header can hold, the data ends early, a number is malformed, not finite
// or not an integer where the type is one, a face has fewer than 3 or more than 255 corners, a
// corner names a vertex that does not exist, or there are no faces.
#include <filesystem>
#include <string_view>

#include "raytracer/geometry/object.hpp"

namespace sweeptrace {

// A name ending in .gz (mesh.ply.gz, as pbrt-v4's scenes ship them) is inflated first, bounded by
// kMaxMeshFileBytes decompressed (gzip_file.hpp, whose errors it throws).
Mesh load_ply(const std::filesystem::path& file);
// The same from bytes already in memory (`name` for messages): the fuzzer's entry.
Mesh parse_ply(std::string_view bytes, const std::string& name);

}  // namespace sweeptrace

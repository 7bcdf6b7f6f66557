#pragma once
// What the OBJ loader reads from the raw text itself, before tinyobjloader: the line of each
// face and its corner count, and every `v` statement's coordinates checked. tinyobjloader stores
// a face's corner count in a byte (256 corners wrap to 0, and the loader would read past the
// face's indices), reads "nan", "inf" or a missing coordinate as 0, and stops a line at a NUL
// byte; none of that can be seen in its output, so it is rejected here, with the line.
//
// Lines end at "\n", "\r\n" or a lone "\r", exactly as tinyobjloader splits them, so the two
// agree on every line whatever the file's line endings; obj_loader.cpp checks that they agree.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sweeptrace {

struct ObjOutline {
    std::vector<std::size_t> face_lines;      // 1-based line of each `f` statement, in file order
    std::vector<std::uint32_t> face_corners;  // its corner count, 3..kMaxObjFaceCorners
    std::size_t vertex_count = 0;             // `v` statements
};

// The most corners tinyobjloader can count in a face.
inline constexpr std::uint32_t kMaxObjFaceCorners = 255;

// Throws InputError "<name>: line N: ..." for a NUL byte, a face with fewer than 3 or more than
// kMaxObjFaceCorners corners, or a `v` whose x, y or z is missing, not a decimal number, or not
// finite in single precision.
ObjOutline outline_obj(const std::string& text, const std::string& name);

}  // namespace sweeptrace

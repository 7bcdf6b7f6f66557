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
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace sweeptrace {

struct ObjOutline {
    std::vector<std::size_t> face_lines;      // 1-based line of each `f` statement, in file order
    std::vector<std::uint32_t> face_corners;  // its corner count, 3..kMaxObjFaceCorners
    std::size_t vertex_count = 0;             // `v` statements
    // Material statements (scene/obj_materials.hpp reads them): the line and its words after the
    // keyword, joined by single spaces (`usemtl`: one name; `mtllib`: one or more files).
    struct Statement {
        std::size_t line = 0;
        std::string value;
    };
    std::vector<Statement> mtllibs, usemtls;
};

// Calls `fn(line, words)` for every line of `text` (1-based, lines split as above; words split
// by space and tab, as tinyobjloader does). Throws InputError "<name>: line N: ..." at a NUL byte.
// The .mtl reader (scene/load_mtl.hpp) splits its files the same way.
void for_each_obj_line(const std::string& text, const std::string& name,
                       const std::function<void(std::size_t, const std::vector<std::string_view>&)>& fn);

// A decimal number as OBJ writers print it: [+-] digits [. digits] [e [+-] digits]; not "nan",
// "inf" or hex.
bool obj_decimal(std::string_view word);

// The most corners tinyobjloader can count in a face.
inline constexpr std::uint32_t kMaxObjFaceCorners = 255;

// Throws InputError "<name>: line N: ..." for a NUL byte, a face with fewer than 3 or more than
// kMaxObjFaceCorners corners, or a `v` whose x, y or z is missing, not a decimal number, or not
// finite in single precision.
ObjOutline outline_obj(const std::string& text, const std::string& name);

}  // namespace sweeptrace

#include "raytracer/scene/obj_outline.hpp"

#include <cmath>
#include <cstdlib>
#include <string_view>

#include "raytracer/input_error.hpp"

namespace sweeptrace {

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }

// The whitespace-separated words of one line (tinyobjloader separates by space and tab only).
std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !blank(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

// A decimal number as OBJ writers print it: [+-] digits [. digits] [e [+-] digits]. Not "nan",
// "inf" or hex, which strtod would take and tinyobjloader would read as 0.
bool decimal(std::string_view w) {
    std::size_t i = 0, digits = 0;
    auto run = [&] {
        std::size_t n = 0;
        while (i < w.size() && w[i] >= '0' && w[i] <= '9') ++i, ++n;
        return n;
    };
    if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
    digits += run();
    if (i < w.size() && w[i] == '.') ++i, digits += run();
    if (digits == 0) return false;
    if (i < w.size() && (w[i] == 'e' || w[i] == 'E')) {
        ++i;
        if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
        if (run() == 0) return false;
    }
    return i == w.size();
}

void check_vertex(const std::vector<std::string_view>& w, const std::string& where) {
    static const char* const kAxis[3] = {"x", "y", "z"};
    for (std::size_t k = 0; k < 3; ++k) {
        if (k + 1 >= w.size()) throw InputError(where + "vertex has no " + kAxis[k] + " coordinate (`v x y z`)");
        const std::string word(w[k + 1]);
        if (!decimal(word))
            throw InputError(where + "vertex " + kAxis[k] + " '" + excerpt(word, 30) + "' is not a decimal number");
        if (!std::isfinite(static_cast<float>(std::strtod(word.c_str(), nullptr))))
            throw InputError(where + "vertex " + kAxis[k] + " " + excerpt(word, 30) +
                             " is not finite in single precision");
    }
}

}  // namespace

ObjOutline outline_obj(const std::string& text, const std::string& name) {
    ObjOutline out;
    std::size_t line = 1, i = 0;
    while (i < text.size()) {
        std::size_t end = i;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r' && text[end] != '\0') ++end;
        const std::string where = name + ": line " + std::to_string(line) + ": ";
        if (end < text.size() && text[end] == '\0') throw InputError(where + "contains a NUL byte (OBJ is text)");
        const std::vector<std::string_view> w = words(std::string_view(text).substr(i, end - i));
        if (!w.empty() && w[0] == "v") {
            check_vertex(w, where);
            ++out.vertex_count;
        } else if (!w.empty() && w[0] == "f") {
            const std::size_t corners = w.size() - 1;
            if (corners < 3 || corners > kMaxObjFaceCorners)
                throw InputError(where + "a face needs 3 to " + std::to_string(kMaxObjFaceCorners) +
                                 " vertices, this one has " + std::to_string(corners));
            out.face_lines.push_back(line);
            out.face_corners.push_back(static_cast<std::uint32_t>(corners));
        }
        i = end;
        if (i < text.size() && text[i] == '\r') {
            ++i;
            if (i < text.size() && text[i] == '\n') ++i;
        } else if (i < text.size()) {
            ++i;
        }
        ++line;
    }
    return out;
}

}  // namespace sweeptrace

#include "raytracer/scene/obj_outline.hpp"

#include <cmath>
#include <cstdlib>
#include <string_view>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/text_file.hpp"

namespace sweeptrace {

// Not "nan", "inf" or hex, which strtod would take and tinyobjloader would read as 0.
bool obj_decimal(std::string_view w) {
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

namespace {

void check_vertex(const std::vector<std::string_view>& w, const std::string& where) {
    static const char* const kAxis[3] = {"x", "y", "z"};
    for (std::size_t k = 0; k < 3; ++k) {
        if (k + 1 >= w.size()) throw InputError(where + "vertex has no " + kAxis[k] + " coordinate (`v x y z`)");
        const std::string word(w[k + 1]);
        if (!obj_decimal(word))
            throw InputError(where + "vertex " + kAxis[k] + " '" + excerpt(word, 30) + "' is not a decimal number");
        if (!std::isfinite(static_cast<float>(std::strtod(word.c_str(), nullptr))))
            throw InputError(where + "vertex " + kAxis[k] + " " + excerpt(word, 30) +
                             " is not finite in single precision");
    }
}

}  // namespace

void for_each_obj_line(const std::string& text, const std::string& name,
                       const std::function<void(std::size_t, const std::vector<std::string_view>&)>& fn) {
    std::size_t line = 1, i = 0;
    while (i < text.size()) {
        std::size_t end = i;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r' && text[end] != '\0') ++end;
        if (end < text.size() && text[end] == '\0')
            throw InputError(name + ": line " + std::to_string(line) + ": contains a NUL byte (OBJ is text)");
        fn(line, words(std::string_view(text).substr(i, end - i)));
        i = end;
        if (i < text.size() && text[i] == '\r') {
            ++i;
            if (i < text.size() && text[i] == '\n') ++i;
        } else if (i < text.size()) {
            ++i;
        }
        ++line;
    }
}

ObjOutline outline_obj(const std::string& text, const std::string& name) {
    ObjOutline out;
    for_each_obj_line(text, name, [&](std::size_t line, const std::vector<std::string_view>& w) {
        if (w.empty()) return;
        const std::string where = name + ": line " + std::to_string(line) + ": ";
        if (w[0] == "v") {
            check_vertex(w, where);
            ++out.vertex_count;
        } else if (w[0] == "f") {
            const std::size_t corners = w.size() - 1;
            if (corners < 3 || corners > kMaxObjFaceCorners)
                throw InputError(where + "a face needs 3 to " + std::to_string(kMaxObjFaceCorners) +
                                 " vertices, this one has " + std::to_string(corners));
            out.face_lines.push_back(line);
            out.face_corners.push_back(static_cast<std::uint32_t>(corners));
        } else if (w[0] == "mtllib" || w[0] == "usemtl") {
            ObjOutline::Statement st{line, {}};
            for (std::size_t k = 1; k < w.size(); ++k) {
                if (k > 1) st.value += ' ';
                st.value.append(w[k]);
            }
            (w[0] == "mtllib" ? out.mtllibs : out.usemtls).push_back(std::move(st));
        }
    });
    return out;
}

}  // namespace sweeptrace

#include "raytracer/scene/load_mtl.hpp"

#include <cstdlib>
#include <string_view>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/obj_outline.hpp"
#include "raytracer/scene/text_file.hpp"

namespace sweeptrace {

namespace {

using Words = std::vector<std::string_view>;

// The largest magnitude a statement's number may have ("inf" in messages): finite, as a float.
constexpr float kInf = 3.0e38f;

// Word k of the statement as a number in [lo, hi]; messages name it by `key` (the keyword, or an
// option of it).
float number(const Words& w, std::size_t k, float lo, float hi, const std::string& where, const std::string& key) {
    if (k >= w.size()) throw InputError(where + key + " needs a number");
    const std::string word(w[k]);
    if (!obj_decimal(word)) throw InputError(where + key + " '" + excerpt(word, 30) + "' is not a decimal number");
    const float v = static_cast<float>(std::strtod(word.c_str(), nullptr));
    if (!(v >= lo && v <= hi))
        throw InputError(where + key + " " + excerpt(word, 30) + " is out of range [" +
                         (lo <= -kInf ? std::string("-inf") : std::to_string(lo)) + ", " +
                         (hi >= kInf ? std::string("inf") : std::to_string(hi)) + "]");
    return v;
}

float number(const Words& w, std::size_t k, float lo, float hi, const std::string& where) {
    return number(w, k, lo, hi, where, std::string(w[0]));
}

// `Kd r g b` or `Kd v` (grey); spectral and CIE XYZ forms are refused.
glm::vec3 colour(const Words& w, float hi, const std::string& where) {
    if (w.size() != 2 && w.size() != 4)
        throw InputError(where + std::string(w[0]) + " needs r g b (or one grey value); spectral and xyz forms are not read");
    if (w.size() == 2) return glm::vec3(number(w, 1, 0.0f, hi, where));
    return {number(w, 1, 0.0f, hi, where), number(w, 2, 0.0f, hi, where), number(w, 3, 0.0f, hi, where)};
}

// `bump`: read the -bm option (the other maps' statements are read past it, as before: it means
// nothing there).
MtlMap map(const Words& w, std::size_t line, const std::string& where, bool bump = false) {
    if (w.size() < 2) throw InputError(where + std::string(w[0]) + " names no file");
    MtlMap out{std::string(w.back()), line};
    // The options before the file: -bm takes one number (the last word is the file, never it).
    for (std::size_t k = 1; bump && k + 1 < w.size(); ++k)
        if (w[k] == "-bm") {
            if (k + 2 >= w.size()) throw InputError(where + std::string(w[0]) + " -bm needs a number before the file");
            out.bm = number(w, ++k, -kInf, kInf, where, std::string(w[0]) + " -bm");
        }
    return out;
}

void read_statement(const Words& w, std::size_t line, const std::string& where, MtlMaterial& m) {
    const std::string_view key = w[0];
    if (key == "Kd") m.kd = colour(w, 1.0f, where);
    else if (key == "Ks") m.ks = colour(w, 1.0f, where);
    else if (key == "Ke") m.ke = colour(w, kInf, where);
    else if (key == "Ns") m.ns = number(w, 1, 0.0f, kInf, where);
    else if (key == "Ni") m.ni = number(w, 1, 0.0f, kInf, where);
    else if (key == "d") m.d = number(w, 1, 0.0f, 1.0f, where);
    else if (key == "Tr") m.d = 1.0f - number(w, 1, 0.0f, 1.0f, where);
    else if (key == "illum") {
        const float v = number(w, 1, 0.0f, 10.0f, where);
        if (v != static_cast<float>(static_cast<int>(v))) throw InputError(where + "illum must be an integer 0..10");
        m.illum = static_cast<int>(v);
    } else if (key == "map_Kd") m.map_kd = map(w, line, where);
    else if (key == "map_Ks") m.map_ks = map(w, line, where);
    else if (key == "map_Bump" || key == "map_bump" || key == "bump") m.map_bump = map(w, line, where, true);
    else if (key == "norm") m.map_norm = map(w, line, where);
}

}  // namespace

std::vector<MtlMaterial> load_mtl(const std::filesystem::path& file) {
    const std::string text = read_text_file(file, "material library", kMaxSceneFileBytes);
    const std::string name = file.string();
    std::vector<MtlMaterial> out;
    for_each_obj_line(text, name, [&](std::size_t line, const Words& w) {
        if (w.empty() || w[0].front() == '#') return;
        const std::string where = name + ": line " + std::to_string(line) + ": ";
        if (w[0] == "newmtl") {
            std::string n;
            for (std::size_t k = 1; k < w.size(); ++k) {
                if (k > 1) n += ' ';
                n.append(w[k]);
            }
            if (n.empty()) throw InputError(where + "newmtl needs a name");
            for (const MtlMaterial& m : out)
                if (m.name == n)
                    throw InputError(where + "material \"" + excerpt(n, 60) + "\" is already defined on line " +
                                     std::to_string(m.line));
            out.push_back(MtlMaterial{});
            out.back().name = n;
            out.back().line = line;
            return;
        }
        static constexpr std::string_view kRead[] = {"Kd", "Ks", "Ke", "Ns", "Ni", "d", "Tr", "illum", "map_Kd",
                                                     "map_Ks", "map_Bump", "map_bump", "bump", "norm"};
        bool known = false;
        for (std::string_view k : kRead) known = known || w[0] == k;
        if (!known) return;
        if (out.empty()) throw InputError(where + std::string(w[0]) + " before any newmtl");
        read_statement(w, line, where, out.back());
    });
    return out;
}

}  // namespace sweeptrace

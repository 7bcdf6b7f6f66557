#include "raytracer/scene/pbrt/pbrt_params.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"

namespace sweeptrace::pbrt {

namespace {

// Values per element for the numeric types (0: any count).
int arity(const std::string& type) {
    if (type == "float" || type == "integer") return 1;
    if (type == "point2" || type == "vector2") return 2;
    if (type == "point3" || type == "vector3" || type == "normal3" || type == "rgb") return 3;
    if (type == "blackbody") return 1;
    return 0;
}

std::string canonical_type(const std::string& t) {
    if (t == "point") return "point3";
    if (t == "vector") return "vector3";
    if (t == "normal") return "normal3";
    if (t == "color") return "rgb";
    return t;
}

bool is_known_type(const std::string& t) {
    return t == "integer" || t == "float" || t == "point2" || t == "vector2" || t == "point3" || t == "vector3" ||
           t == "normal3" || t == "rgb" || t == "spectrum" || t == "blackbody" || t == "bool" || t == "string" ||
           t == "texture";
}

bool parse_number(const std::string& s, double& out) {
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (b != e && *b == '+') ++b;
    const auto r = std::from_chars(b, e, out);
    return r.ec == std::errc() && r.ptr == e && std::isfinite(out);
}

}  // namespace

ParamList parse_params(const std::vector<Token>& tokens, std::size_t& pos, const Where& file, const Diagnostics& d) {
    ParamList list;
    while (pos < tokens.size() && tokens[pos].kind == Token::Kind::String) {
        const Token& decl = tokens[pos++];
        Where at = file;
        at.line = decl.line;
        // "type name": exactly two words.
        const std::string& s = decl.text;
        const std::size_t a = s.find_first_not_of(" \t");
        const std::size_t a_end = a == std::string::npos ? a : s.find_first_of(" \t", a);
        const std::size_t b = a_end == std::string::npos ? a_end : s.find_first_not_of(" \t", a_end);
        const std::size_t b_end = b == std::string::npos ? b : s.find_first_of(" \t", b);
        if (a == std::string::npos || b == std::string::npos ||
            (b_end != std::string::npos && s.find_first_not_of(" \t", b_end) != std::string::npos))
            d.fail(at, "parameter \"" + excerpt(s) + "\" must be \"type name\", e.g. \"float radius\"");
        Param p;
        p.type = canonical_type(s.substr(a, a_end - a));
        p.name = s.substr(b, b_end == std::string::npos ? std::string::npos : b_end - b);
        p.where = at;
        if (!is_known_type(p.type))
            d.fail(at, "unknown parameter type \"" + excerpt(p.type) +
                           "\" (known: integer, float, point2, vector2, point3, vector3, normal3, rgb, spectrum, "
                           "blackbody, bool, string, texture)");
        std::vector<const Token*> values;
        if (pos < tokens.size() && tokens[pos].kind == Token::Kind::Open) {
            ++pos;
            while (pos < tokens.size() && tokens[pos].kind != Token::Kind::Close) {
                if (tokens[pos].kind == Token::Kind::Open) d.fail(at, "'[' inside the values of \"" + excerpt(s) + "\": close the list with ']'");
                values.push_back(&tokens[pos++]);
            }
            if (pos >= tokens.size()) d.fail(at, "the values of \"" + excerpt(s) + "\" are not closed: add ']'");
            ++pos;
        } else if (pos < tokens.size() && tokens[pos].kind != Token::Kind::Close) {
            values.push_back(&tokens[pos++]);
        }
        if (values.empty()) d.fail(at, "parameter \"" + excerpt(s) + "\" has no value");
        std::uint64_t text_bytes = 0;
        for (const Token* v : values) text_bytes += v->text.size();
        charge_load_memory(values.size() * std::max(sizeof(double), sizeof(std::string)) + text_bytes, at.text(),
                           "parameter \"" + excerpt(s) + "\" (" + std::to_string(values.size()) + " values)");
        const bool wants_strings = p.type == "string" || p.type == "texture" || p.type == "bool";
        const bool maybe_strings = p.type == "spectrum";
        for (const Token* v : values) {
            double x = 0.0;
            if (p.type == "bool") {
                if (v->text != "true" && v->text != "false")
                    d.fail(at, "\"" + excerpt(s) + "\" must be true or false, got \"" + excerpt(v->text) + "\"");
                p.strings.push_back(v->text);
            } else if (wants_strings || (maybe_strings && v->kind == Token::Kind::String)) {
                if (v->kind != Token::Kind::String)
                    d.fail(at, "\"" + excerpt(s) + "\" takes quoted strings, got " + excerpt(v->text));
                p.strings.push_back(v->text);
            } else {
                if (v->kind != Token::Kind::Word || !parse_number(v->text, x))
                    d.fail(at, "\"" + excerpt(s) + "\" takes finite numbers, got \"" + excerpt(v->text) + "\"");
                if (p.type == "integer" && (x != std::floor(x) || x < -2147483648.0 || x > 2147483647.0))  // an int
                    d.fail(at, "\"" + excerpt(s) + "\" takes integers, got " + excerpt(v->text));
                // pbrt-v4 keeps parameters as 32-bit floats: 1e300 is infinity there, and would be
                // here once written to the scene (a lens radius, a light's L, an ISO).
                if (std::fabs(x) > double(std::numeric_limits<float>::max()))
                    d.fail(at, "\"" + excerpt(s) + "\" takes numbers a 32-bit float holds (|x| <= 3.4e38), got " + excerpt(v->text));
                p.numbers.push_back(x);
            }
        }
        if (!p.numbers.empty() && !p.strings.empty())
            d.fail(at, "\"" + excerpt(s) + "\" mixes numbers and strings");
        if (p.type == "spectrum" && p.strings.size() > 1) d.fail(at, "\"" + excerpt(s) + "\" takes one named spectrum");
        if (p.type == "spectrum" && !p.numbers.empty() && p.numbers.size() % 2 != 0)
            d.fail(at, "\"" + excerpt(s) + "\" takes (wavelength, value) pairs: an even count of numbers");
        if (const int k = arity(p.type); k > 1 && p.numbers.size() % static_cast<std::size_t>(k) != 0)
            d.fail(at, "\"" + excerpt(s) + "\" takes a multiple of " + std::to_string(k) + " numbers, got " +
                           std::to_string(p.numbers.size()));
        if (p.type == "rgb" && p.numbers.size() != 3) d.fail(at, "\"" + excerpt(s) + "\" takes 3 numbers");
        if (p.type == "blackbody" && p.numbers.size() != 1) d.fail(at, "\"" + excerpt(s) + "\" takes one temperature");
        list.params.push_back(std::move(p));
    }
    return list;
}

std::uint64_t ParamList::bytes() const {
    std::uint64_t n = 0;
    for (const Param& p : params) {
        n += sizeof(Param) + p.numbers.size() * sizeof(double) + p.strings.size() * sizeof(std::string);
        for (const std::string& s : p.strings) n += s.size();
    }
    return n;
}

const Param* ParamList::find(std::string_view name) const {
    // The last of repeated names wins, as in pbrt.
    for (auto it = params.rbegin(); it != params.rend(); ++it)
        if (it->name == name) {
            for (const Param& q : params)
                if (q.name == name) q.used = true;
            return &*it;
        }
    return nullptr;
}

bool ParamList::has(std::string_view name) const {
    for (const Param& p : params)
        if (p.name == name) return true;
    return false;
}

namespace {

const Param* typed(const ParamList& l, std::string_view name, std::initializer_list<std::string_view> types,
                   const Diagnostics& d) {
    const Param* p = l.find(name);
    if (!p) return nullptr;
    for (std::string_view t : types)
        if (p->type == t) return p;
    std::string names;
    for (std::string_view t : types) names += (names.empty() ? "\"" : " or \"") + std::string(t) + " " + std::string(name) + "\"";
    d.fail(p->where, "\"" + p->type + " " + p->name + "\" has the wrong type: write " + names);
}

}  // namespace

double ParamList::get_float(std::string_view name, double fallback, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"float"}, d);
    if (!p) return fallback;
    if (p->numbers.size() != 1) d.fail(p->where, "\"float " + p->name + "\" takes one number");
    return p->numbers[0];
}

long long ParamList::get_int(std::string_view name, long long fallback, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"integer"}, d);
    if (!p) return fallback;
    if (p->numbers.size() != 1) d.fail(p->where, "\"integer " + p->name + "\" takes one number");
    return static_cast<long long>(p->numbers[0]);
}

bool ParamList::get_bool(std::string_view name, bool fallback, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"bool"}, d);
    if (!p) return fallback;
    if (p->strings.size() != 1) d.fail(p->where, "\"bool " + p->name + "\" takes one value");
    return p->strings[0] == "true";
}

std::string ParamList::get_string(std::string_view name, const std::string& fallback, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"string"}, d);
    if (!p) return fallback;
    if (p->strings.size() != 1) d.fail(p->where, "\"string " + p->name + "\" takes one string");
    return p->strings[0];
}

std::optional<glm::dvec3> ParamList::get_point3(std::string_view name, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"point3", "vector3", "normal3"}, d);
    if (!p) return std::nullopt;
    if (p->numbers.size() != 3) d.fail(p->where, "\"" + p->type + " " + p->name + "\" takes 3 numbers here");
    return glm::dvec3(p->numbers[0], p->numbers[1], p->numbers[2]);
}

std::vector<double> ParamList::get_floats(std::string_view name, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"float", "point2", "vector2", "point3", "vector3", "normal3"}, d);
    return p ? p->numbers : std::vector<double>{};
}

std::vector<long long> ParamList::get_ints(std::string_view name, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"integer"}, d);
    std::vector<long long> out;
    if (p)
        for (double x : p->numbers) out.push_back(static_cast<long long>(x));
    return out;
}

std::vector<std::string> ParamList::get_strings(std::string_view name, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"string"}, d);
    return p ? p->strings : std::vector<std::string>{};
}

std::optional<SpectrumValue> ParamList::get_spectrum(std::string_view name, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"rgb", "spectrum", "blackbody", "float", "texture"}, d);
    if (!p) return std::nullopt;
    SpectrumValue v;
    v.where = p->where;
    if (p->type == "rgb") {
        v.rgb = glm::dvec3(p->numbers[0], p->numbers[1], p->numbers[2]);
    } else if (p->type == "float") {
        if (p->numbers.size() != 1) d.fail(p->where, "\"float " + p->name + "\" takes one number");
        v.rgb = glm::dvec3(p->numbers[0]);
    } else if (p->type == "blackbody") {
        v.kind = SpectrumValue::Kind::Blackbody;
        v.samples = p->numbers;
    } else if (p->type == "texture") {
        if (p->strings.size() != 1) d.fail(p->where, "\"texture " + p->name + "\" takes one texture name");
        v.kind = SpectrumValue::Kind::Texture;
        v.name = p->strings[0];
    } else if (!p->strings.empty()) {
        v.kind = SpectrumValue::Kind::Named;
        v.name = p->strings[0];
    } else {
        v.kind = SpectrumValue::Kind::Sampled;
        v.samples = p->numbers;
    }
    return v;
}

std::optional<double> ParamList::get_float_or_texture(std::string_view name, std::string& texture, const Diagnostics& d) const {
    const Param* p = typed(*this, name, {"float", "texture"}, d);
    texture.clear();
    if (!p) return std::nullopt;
    if (p->type == "texture") {
        if (p->strings.size() != 1) d.fail(p->where, "\"texture " + p->name + "\" takes one texture name");
        texture = p->strings[0];
        return 0.0;
    }
    if (p->numbers.size() != 1) d.fail(p->where, "\"float " + p->name + "\" takes one number");
    return p->numbers[0];
}

void ParamList::warn_unused(const std::string& what, Diagnostics& d, const std::string& kind) const {
    for (const Param& p : params)
        if (!p.used)
            d.warn(p.where, (kind.empty() ? what : kind) + " parameter " + p.name,
                   what + ": parameter \"" + p.type + " " + p.name + "\" is not supported (ignored)");
}

}  // namespace sweeptrace::pbrt

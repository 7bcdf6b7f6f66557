#pragma once
// A pbrt parameter list: `"type name" value` or `"type name" [ values ]`, after a directive's
// fixed arguments. Types (pbrt.org/fileformat-v4, "Parameter lists"): integer, float, point2,
// vector2, point3, vector3, normal3 (and pbrt-v3's point, vector, normal, color), rgb, spectrum
// (numbers, or a named spectrum such as "metal-Au-eta"), blackbody, bool, string, texture.
// The parser checks each value's kind and count for its type (a "float" of strings is malformed);
// the readers take defaults, mark what they read, and the importer warns about every parameter
// nothing read (one warning per kind), so no parameter is dropped silently.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt/pbrt_tokenizer.hpp"

namespace sweeptrace::pbrt {

struct Param {
    std::string type;  // as written, pbrt-v3 aliases mapped: point -> point3, color -> rgb, ...
    std::string name;
    std::vector<double> numbers;
    std::vector<std::string> strings;  // string, texture, a named spectrum; bools as "true"/"false"
    Where where;
    mutable bool used = false;
};

// A spectrum-typed value as written: rgb, a named spectrum, sampled (wavelength, value) pairs, a
// blackbody temperature, or a texture's name.
struct SpectrumValue {
    enum class Kind { Rgb, Named, Sampled, Blackbody, Texture } kind = Kind::Rgb;
    glm::dvec3 rgb{0.0};
    std::string name;
    std::vector<double> samples;
    Where where;
};

class ParamList {
public:
    std::vector<Param> params;

    const Param* find(std::string_view name) const;  // marks it used
    bool has(std::string_view name) const;            // does not mark
    std::uint64_t bytes() const;                      // the memory the values take, for the load budget

    // Typed readers: a parameter of this name but another type fails (file:line).
    double get_float(std::string_view name, double fallback, const Diagnostics& d) const;
    long long get_int(std::string_view name, long long fallback, const Diagnostics& d) const;
    bool get_bool(std::string_view name, bool fallback, const Diagnostics& d) const;
    std::string get_string(std::string_view name, const std::string& fallback, const Diagnostics& d) const;
    std::optional<glm::dvec3> get_point3(std::string_view name, const Diagnostics& d) const;
    std::vector<double> get_floats(std::string_view name, const Diagnostics& d) const;  // float, point*, normal, ...
    std::vector<long long> get_ints(std::string_view name, const Diagnostics& d) const;
    std::vector<std::string> get_strings(std::string_view name, const Diagnostics& d) const;
    // spectrum, rgb, blackbody, float (a grey) or texture.
    std::optional<SpectrumValue> get_spectrum(std::string_view name, const Diagnostics& d) const;
    // A float that may be a "texture": the texture's name in `texture`.
    std::optional<double> get_float_or_texture(std::string_view name, std::string& texture, const Diagnostics& d) const;

    // Each parameter nothing read, once per (kind, name), `kind` defaulting to `what` (give it
    // when `what` names one instance, as a texture's name does): "<what>: parameter "type name" ignored".
    void warn_unused(const std::string& what, Diagnostics& d, const std::string& kind = {}) const;
};

// Reads parameters from tokens[pos] on while the next token is a quoted string, advancing pos.
ParamList parse_params(const std::vector<Token>& tokens, std::size_t& pos, const Where& file, const Diagnostics& d);

}  // namespace sweeptrace::pbrt

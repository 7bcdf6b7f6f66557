// pbrt-v4 textures and spectra as our JSON's values (the texture half of MaterialTranslator).
#include <cmath>
#include <system_error>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/pbrt/pbrt_materials.hpp"
#include "raytracer/scene/pbrt/pbrt_spectra.hpp"

namespace sweeptrace::pbrt {

using nlohmann::json;

FileNames::FileNames(const std::filesystem::path& main_file, const std::filesystem::path& output_dir) {
    std::error_code ec;
    base_ = main_file.parent_path();
    out_ = std::filesystem::absolute(output_dir.empty() ? std::filesystem::path(".") : output_dir, ec).lexically_normal();
}

std::filesystem::path FileNames::resolve(const std::string& name) const {
    // As the user spelled the main file (relative to the working folder when it was): messages
    // then name files the way the user sees them.
    const std::filesystem::path p(name);
    return (p.is_absolute() ? p : base_ / p).lexically_normal();
}

std::string FileNames::json_path(const std::string& name) const {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::absolute(resolve(name), ec).lexically_normal();
    const std::filesystem::path rel = p.lexically_relative(out_);
    return (rel.empty() ? p : rel).generic_string();
}

namespace {

bool is_linear_format(const std::string& ext) { return ext == ".exr" || ext == ".hdr" || ext == ".pfm"; }

}  // namespace

glm::dvec3 MaterialTranslator::spectrum_rgb(const SpectrumValue& v, const std::string& what) {
    switch (v.kind) {
    case SpectrumValue::Kind::Rgb: return v.rgb;
    case SpectrumValue::Kind::Blackbody: return blackbody_rgb(v.samples[0]);
    case SpectrumValue::Kind::Sampled:
        diag_.warn(v.where, "sampled spectrum", what + ": a sampled spectrum is approximated by its values at 610, 550 and 465 nm");
        return sampled_rgb(v.samples);
    case SpectrumValue::Kind::Named:
        if (v.name.rfind("stdillum-", 0) == 0) {
            if (v.name != "stdillum-D65")
                diag_.warn(v.where, "illuminant " + v.name, what + ": illuminant \"" + excerpt(v.name) + "\" is approximated as white (D65)");
            return glm::dvec3(1.0);
        }
        diag_.warn(v.where, "named spectrum " + v.name,
                   what + ": named spectrum \"" + excerpt(v.name) + "\" is not supported here (grey 0.5 instead)");
        return glm::dvec3(0.5);
    case SpectrumValue::Kind::Texture: break;
    }
    return glm::dvec3(0.5);
}

json MaterialTranslator::colour(const ParamList& p, const std::string& name, const glm::dvec3& fallback, bool albedo,
                                const std::string& what) {
    const std::optional<SpectrumValue> v = spectrum(p, name, what);
    auto clamp_albedo = [&](glm::dvec3 c, const Where& where) {
        if (albedo && (glm::any(glm::greaterThan(c, glm::dvec3(1.0))) || glm::any(glm::lessThan(c, glm::dvec3(0.0))))) {
            diag_.warn(where, "albedo outside [0, 1]", what + ": \"" + name + "\" outside [0, 1] is clamped to it");
            c = glm::clamp(c, glm::dvec3(0.0), glm::dvec3(1.0));
        }
        return rgb_json(c);
    };
    if (!v) return rgb_json(fallback);
    if (v->kind != SpectrumValue::Kind::Texture) return clamp_albedo(spectrum_rgb(*v, what), v->where);
    const auto it = spectrum_textures_.find(v->name);
    if (it == spectrum_textures_.end()) {
        if (float_textures_.count(v->name)) {
            // pbrt-v4 reads a float texture here too only by name clash; say so and use it as grey.
            diag_.fail(v->where, "\"texture " + name + "\" names a float texture \"" + excerpt(v->name) +
                                     "\": define it with Texture \"" + excerpt(v->name) + "\" \"spectrum\" ...");
        }
        diag_.fail(v->where, "\"texture " + name + "\": no spectrum texture named \"" + excerpt(v->name) +
                                 "\" (define it with Texture before the material)");
    }
    if (it->second.is_array()) return clamp_albedo(glm::dvec3(it->second[0], it->second[1], it->second[2]), v->where);
    return it->second;
}

glm::dvec3 MaterialTranslator::emitted(const ParamList& p, const std::string& name, const std::string& what) {
    const std::optional<SpectrumValue> v = spectrum(p, name, what);
    if (!v) return glm::dvec3(1.0);  // the colour space's illuminant, luminance 1
    if (v->kind == SpectrumValue::Kind::Texture) diag_.fail(v->where, what + ": \"" + name + "\" cannot be a texture");
    return glm::max(spectrum_rgb(*v, what), glm::dvec3(0.0));
}

void MaterialTranslator::define_texture(const std::string& name, const std::string& kind, const Statement& s) {
    const ParamList& p = s.params;
    const bool is_float = kind == "float";
    if (!is_float && kind != "spectrum")
        diag_.fail(s.where, "Texture \"" + excerpt(name) + "\": the second argument is \"float\" or \"spectrum\", got \"" +
                                excerpt(kind) + "\"");
    const std::string what = "Texture \"" + excerpt(name) + "\" (" + s.type + ")";
    const json grey = is_float ? json(0.5) : rgb_json(glm::dvec3(0.5));
    auto value_of = [&](const std::string& param, double fallback, bool float_param = false) -> json {
        if (is_float || float_param) {
            std::string tex;
            const std::optional<double> x = p.get_float_or_texture(param, tex, diag_);
            if (!x) return fallback;
            if (tex.empty()) return *x;
            const auto it = float_textures_.find(tex);
            if (it == float_textures_.end()) diag_.fail(s.where, what + ": no float texture named \"" + excerpt(tex) + "\"");
            return it->second;
        }
        const std::optional<SpectrumValue> v = spectrum(p, param, what);
        if (!v) return rgb_json(glm::dvec3(fallback));
        if (v->kind != SpectrumValue::Kind::Texture) return rgb_json(spectrum_rgb(*v, what));
        const auto it = spectrum_textures_.find(v->name);
        if (it == spectrum_textures_.end()) diag_.fail(v->where, what + ": no spectrum texture named \"" + excerpt(v->name) + "\"");
        return it->second;
    };
    auto is_constant = [](const json& j) { return j.is_number() || j.is_array(); };
    auto times = [](const json& a, double k) -> json {
        if (a.is_number()) return a.get<double>() * k;
        return json::array({a[0].get<double>() * k, a[1].get<double>() * k, a[2].get<double>() * k});
    };
    // pbrt-v4's 2D mapping (imagemap, checkerboard): "uv" with uscale, vscale, udelta, vdelta is
    // our uv_scale and uv_offset; the other mappings (spherical, cylindrical, planar) are not ours.
    auto uv_mapping = [&](json& texture) {
        if (const std::string mapping = p.get_string("mapping", "uv", diag_); mapping != "uv") {
            diag_.warn(s.where, "texture mapping " + mapping, "Texture: mapping \"" + excerpt(mapping) + "\" is not supported (the surface's uv used)");
            for (const char* q : {"v1", "v2"}) p.find(q);
        }
        const double su = p.get_float("uscale", 1.0, diag_), sv = p.get_float("vscale", 1.0, diag_);
        const double du = p.get_float("udelta", 0.0, diag_), dv = p.get_float("vdelta", 0.0, diag_);
        if (su == 0.0 || sv == 0.0) diag_.fail(s.where, what + ": \"uscale\" and \"vscale\" must not be 0");
        if (su != 1.0 || sv != 1.0) texture["uv_scale"] = {su, sv};
        if (du != 0.0 || dv != 0.0) texture["uv_offset"] = {du, dv};
    };
    json out = grey;
    if (s.type == "constant") {
        out = value_of("value", 1.0);
    } else if (s.type == "scale") {
        // pbrt-v4: "scale" is a float texture whatever the kind of "tex". Constants multiply out, a
        // checker's colours are scaled, an image gets our "multiply".
        const json tex = value_of("tex", 1.0), scale = value_of("scale", 1.0, true);
        auto scaled_image = [&](const json& image, const json& k) {
            json o = image;
            glm::dvec3 m = o["image"].contains("multiply") ? glm::dvec3(o["image"]["multiply"][0], o["image"]["multiply"][1], o["image"]["multiply"][2])
                                                           : glm::dvec3(1.0);
            m *= k.is_number() ? glm::dvec3(k.get<double>()) : glm::dvec3(k[0].get<double>(), k[1].get<double>(), k[2].get<double>());
            o["image"]["multiply"] = rgb_json(m);
            return o;
        };
        if (is_constant(tex) && scale.is_number()) out = times(tex, scale.get<double>());
        else if (!is_constant(tex) && scale.is_number() && tex.contains("checker")) {
            out = tex;
            out["checker"]["a"] = times(tex["checker"]["a"], scale.get<double>());
            out["checker"]["b"] = times(tex["checker"]["b"], scale.get<double>());
        } else if (!is_constant(tex) && scale.is_number() && tex.contains("image")) {
            out = scaled_image(tex, scale);
        } else if (is_constant(tex) && !is_constant(scale) && scale.contains("image")) {
            out = scaled_image(scale, tex);  // a constant colour times a float image
        } else {
            diag_.warn(s.where, "texture scale of textures", what + ": a texture scaled by another texture is not supported (the first one, unscaled)");
            out = is_constant(tex) ? scale : tex;
        }
    } else if (s.type == "checkerboard") {
        const json a = value_of("tex1", 1.0), b = value_of("tex2", 0.0);
        if (p.get_int("dimension", 2, diag_) != 2)
            diag_.warn(s.where, "checkerboard 3D", what + ": a 3D checkerboard is drawn as the 2D one in uv");
        if (!is_constant(a) || !is_constant(b)) {
            diag_.warn(s.where, "checkerboard of textures", what + ": checks made of textures are not supported (their defaults 1 and 0 used)");
        }
        out = json{{"checker",
                    {{"a", is_constant(a) ? a : (is_float ? json(1.0) : rgb_json(glm::dvec3(1.0)))},
                     {"b", is_constant(b) ? b : (is_float ? json(0.0) : rgb_json(glm::dvec3(0.0)))},
                     {"scale", 1.0}}}};
        json& c = out["checker"];
        uv_mapping(c);
        // Equal u and v scales without offsets: our checker's own "scale", as people write it.
        if (c.contains("uv_scale") && !c.contains("uv_offset") && c["uv_scale"][0] == c["uv_scale"][1] && c["uv_scale"][0].get<double>() > 0.0) {
            c["scale"] = c["uv_scale"][0];
            c.erase("uv_scale");
        }
    } else if (s.type == "imagemap") {
        const std::string file = p.get_string("filename", "", diag_);
        if (file.empty()) diag_.fail(s.where, what + ": needs \"string filename\"");
        const std::string ext = lowercase_extension(file);
        const bool eight_bit = is_8bit_srgb(file);  // image.hpp's list: display values, sRGB-coded
        if (const std::string problem = file_kind_problem(files_.resolve(file)); !problem.empty())
            diag_.fail(s.where, what + ": image \"" + excerpt(file) + "\" " + problem + " (looked for " + files_.resolve(file).string() + ")");
        const std::string encoding = p.get_string("encoding", is_linear_format(ext) ? "linear" : "sRGB", diag_);
        const std::string wrap = p.get_string("wrap", "repeat", diag_);
        if (!eight_bit && !is_linear_format(ext)) {
            diag_.warn(s.where, "image format " + ext, what + ": image format \"" + excerpt(ext) +
                                                            "\" is not read (png, jpg, tga, exr, hdr, pfm are); a constant 0.5 instead");
            for (const char* q : {"scale", "invert", "mapping", "uscale", "vscale", "udelta", "vdelta", "v1", "v2"}) p.find(q);
        } else {
            json image{{"file", files_.json_path(file)}};
            if (wrap == "clamp") image["wrap"] = "clamp";
            else if (wrap == "black") {
                diag_.warn(s.where, "wrap black", what + ": wrap \"black\" is approximated by \"clamp\"");
                image["wrap"] = "clamp";
            } else if (wrap != "repeat")
                diag_.warn(s.where, "wrap " + wrap, what + ": wrap \"" + excerpt(wrap) + "\" is not supported (repeat used)");
            // An 8-bit image's reading: ours by default is sRGB for colours and data for numbers;
            // pbrt's "encoding" (default sRGB for 8-bit files) says which, for either kind.
            if (eight_bit) {
                if (encoding == "sRGB" || encoding == "linear") {
                    if ((encoding == "linear") != is_float) image["encoding"] = encoding;
                } else {
                    diag_.warn(s.where, "image encoding", what + ": encoding \"" + excerpt(encoding) + "\" is approximated by sRGB");
                    if (is_float) image["encoding"] = "sRGB";
                }
            }
            if (const double k = p.get_float("scale", 1.0, diag_); k != 1.0) image["multiply"] = rgb_json(glm::dvec3(k));
            if (p.get_bool("invert", false, diag_)) image["invert"] = true;
            uv_mapping(image);
            out = json{{"image", image}};
        }
        // Filtering (MIP maps, EWA) changes only how texels are averaged: ours is bilinear.
        p.find("filter");
        p.find("maxanisotropy");
    } else {
        diag_.warn(s.where, "texture " + s.type, "Texture class \"" + excerpt(s.type) + "\" is not supported (a constant 0.5 instead)");
        for (const Param& q : p.params) q.used = true;
    }
    p.warn_unused(what, diag_, "Texture (" + s.type + ")");
    (is_float ? float_textures_ : spectrum_textures_)[name] = out;
}

}  // namespace sweeptrace::pbrt

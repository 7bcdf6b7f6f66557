// pbrt-v4 materials as ours (the material half of MaterialTranslator; textures: pbrt_textures.cpp).
#include <algorithm>
#include <cmath>
#include <system_error>
#include <utility>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/named_metals.hpp"
#include "raytracer/scene/pbrt/pbrt_materials.hpp"
#include "raytracer/scene/pbrt/pbrt_spectra.hpp"
#include "raytracer/scene/text_file.hpp"

namespace sweeptrace::pbrt {

using nlohmann::json;

json rgb_json(const glm::dvec3& c) { return json::array({c.r, c.g, c.b}); }

json MaterialTranslator::roughness(const ParamList& p, const std::string& what, const std::string& prefix) {
    std::string tex, utex, vtex;
    const std::optional<double> r = p.get_float_or_texture(prefix + "roughness", tex, diag_);
    const std::optional<double> u = p.get_float_or_texture(prefix + "uroughness", utex, diag_);
    const std::optional<double> v = p.get_float_or_texture(prefix + "vroughness", vtex, diag_);
    const bool remap = p.get_bool("remaproughness", true, diag_);
    const Param* where = p.find(prefix + "roughness");
    if (!where) where = p.find(prefix + "uroughness");
    const Where at = where ? where->where : Where{};
    // Textured roughness: passed through, but our texture is read as sqrt(alpha) directly.
    const std::string any_tex = !utex.empty() ? utex : !vtex.empty() ? vtex : tex;
    if (!any_tex.empty()) {
        const auto it = float_textures_.find(any_tex);
        if (it == float_textures_.end()) diag_.fail(at, what + ": no float texture named \"" + excerpt(any_tex) + "\"");
        if (it->second.is_number()) {
            // a constant texture: converted like a plain number below
        } else {
            diag_.warn(at, "roughness texture", what + ": a roughness texture is used as our roughness (sqrt of GGX alpha) without pbrt's remapping: approximated");
            return it->second;
        }
    }
    auto value = [&](const std::optional<double>& x, const std::string& t) -> double {
        if (!t.empty()) return float_textures_.at(t).get<double>();
        return x ? *x : 0.0;
    };
    const double rough = value(r, tex);
    const double ur = (u || !utex.empty()) ? value(u, utex) : rough;
    const double vr = (v || !vtex.empty()) ? value(v, vtex) : rough;
    auto alpha_of = [&](double x) { return remap ? std::sqrt(std::max(0.0, x)) : std::max(0.0, x); };
    double alpha = alpha_of(ur);
    if (ur != vr) {
        alpha = std::sqrt(alpha_of(ur) * alpha_of(vr));
        diag_.warn(at, "anisotropic roughness", what + ": uroughness != vroughness; our GGX is isotropic: alpha = sqrt(alpha_u alpha_v) (approximated)");
    }
    if (alpha > 1.0) {
        diag_.warn(at, "roughness over 1", what + ": a GGX alpha over 1 is clamped to 1 (our roughness 1)");
        alpha = 1.0;
    }
    return std::sqrt(alpha);
}

double MaterialTranslator::ior(const ParamList& p, const std::string& name, const std::string& what) {
    const std::optional<SpectrumValue> v = spectrum(p, name, what);
    if (!v) return 1.5;
    switch (v->kind) {
    case SpectrumValue::Kind::Rgb:
        if (v->rgb.r != v->rgb.g || v->rgb.g != v->rgb.b)
            diag_.warn(v->where, "coloured eta", what + ": an rgb \"" + name + "\" varies by colour; its green value is used (no dispersion)");
        return v->rgb.g;
    case SpectrumValue::Kind::Named:
        if (auto n = named_glass_ior(v->name)) {
            diag_.warn(v->where, "dispersion", what + ": \"" + excerpt(v->name) + "\" is approximated by its index at 587.6 nm (no dispersion)");
            return *n;
        }
        diag_.warn(v->where, "eta " + v->name, what + ": unknown named spectrum \"" + excerpt(v->name) + "\" for \"" + name + "\" (1.5 instead)");
        return 1.5;
    case SpectrumValue::Kind::Sampled:
        diag_.warn(v->where, "dispersion", what + ": a sampled \"" + name + "\" is approximated by its value at 550 nm (no dispersion)");
        return sampled_rgb(v->samples).g;
    default:
        diag_.warn(v->where, "eta " + name, what + ": \"" + name + "\" of this type is not supported (1.5 instead)");
        return 1.5;
    }
}

json MaterialTranslator::conductor(const ParamList& p, const std::string& what, const std::string& prefix) {
    json m{{"type", "conductor"}};
    const std::optional<SpectrumValue> refl = spectrum(p, "reflectance", what);
    const std::optional<SpectrumValue> eta = spectrum(p, prefix + "eta", what);
    const std::optional<SpectrumValue> k = spectrum(p, prefix + "k", what);
    if (refl) {
        // pbrt-v4: with "reflectance" r, eta = 1 and k = 2 sqrt(r) / sqrt(1 - r): normal incidence reflects r.
        if (refl->kind == SpectrumValue::Kind::Texture) {
            diag_.warn(refl->where, "textured conductor reflectance",
                       what + ": a textured \"reflectance\" becomes our metal (Schlick, F0 = the texture): approximated");
            json metal{{"type", "metal"}, {"albedo", colour(p, "reflectance", glm::dvec3(1.0), true, what)}};
            metal["roughness"] = roughness(p, what, prefix);
            return metal;
        }
        glm::dvec3 r = glm::clamp(spectrum_rgb(*refl, what), glm::dvec3(0.0), glm::dvec3(1.0));
        if (glm::any(glm::greaterThan(r, glm::dvec3(0.9999)))) {
            diag_.warn(refl->where, "conductor reflectance 1", what + ": a \"reflectance\" of 1 is clamped to 0.9999 (k would be infinite)");
            r = glm::min(r, glm::dvec3(0.9999));
        }
        m["eta"] = rgb_json(glm::dvec3(1.0));
        m["k"] = rgb_json(2.0 * glm::sqrt(r) / glm::sqrt(1.0 - r));
    } else {
        conductor_eta_k(eta, k, what, m);
    }
    m["roughness"] = roughness(p, what, prefix);
    return m;
}

namespace {

// The named metal a spectrum names, for that part ("eta" or "k"), or nullopt.
std::optional<std::string> metal_part(const std::optional<SpectrumValue>& v, const char* part) {
    std::string got;
    if (!v || v->kind != SpectrumValue::Kind::Named) return std::nullopt;
    auto metal = named_metal(v->name, got);
    return metal && got == part ? metal : std::nullopt;
}

bool is_sampled(const std::optional<SpectrumValue>& v) { return v && v->kind == SpectrumValue::Kind::Sampled; }

bool is_plain(const std::optional<SpectrumValue>& v) {
    return v && (v->kind == SpectrumValue::Kind::Rgb || v->kind == SpectrumValue::Kind::Sampled ||
                 v->kind == SpectrumValue::Kind::Blackbody);
}

std::string kind_of(const std::optional<SpectrumValue>& v) {
    if (!v) return "not given";
    switch (v->kind) {
    case SpectrumValue::Kind::Rgb: return "rgb";
    case SpectrumValue::Kind::Blackbody: return "blackbody";
    case SpectrumValue::Kind::Texture: return "a texture";
    case SpectrumValue::Kind::Sampled: return v->name.empty() ? "sampled" : "the file \"" + excerpt(v->name) + "\"";
    case SpectrumValue::Kind::Named: break;
    }
    return "\"" + excerpt(v->name) + "\"";
}

}  // namespace

// pbrt-v4's conductor: eta and k, each copper's (metal-Cu-eta, metal-Cu-k) when not given. Both named
// metals: ours by name (two different ones: eta's, or the one given, warned); both sampled (inline
// or files): the named metals' reflectance fit; both rgb (or rgb and sampled): per channel. Any
// other pairing reduces each part alone, with a warning.
void MaterialTranslator::conductor_eta_k(const std::optional<SpectrumValue>& eta, const std::optional<SpectrumValue>& k,
                                         const std::string& what, json& m) {
    const auto eta_metal = metal_part(eta, "eta"), k_metal = metal_part(k, "k");
    if ((eta_metal || !eta) && (k_metal || !k)) {
        const std::string e = eta_metal.value_or("Cu"), kk = k_metal.value_or("Cu");
        const std::string& used = eta ? e : kk;  // eta's metal, or the one given
        if (e != kk)
            diag_.warn(eta ? eta->where : k->where, "mixed metals",
                       what + ": eta of " + e + " with k of " + kk + (eta && k ? "" : " (pbrt-v4's default for the one not given)") +
                           ": our named metal " + used + " is used for both");
        m["metal"] = used;
        return;
    }
    glm::dvec3 e, kk;
    if (is_sampled(eta) && is_sampled(k)) {
        auto key = std::make_pair(eta->samples, k->samples);
        auto it = conductor_fits_.find(key);
        if (it == conductor_fits_.end()) it = conductor_fits_.emplace(std::move(key), fit_conductor_rgb(eta->samples, k->samples)).first;
        if (!covers_visible(eta->samples) || !covers_visible(k->samples))
            diag_.warn(eta->where, "conductor spectrum range", what + ": a sampled eta or k that does not span 380-780 nm is held at its ends (pbrt-v4 reads 0 past them)");
        e = it->second.eta;
        kk = it->second.k;
    } else if (is_plain(eta) && is_plain(k)) {
        e = spectrum_rgb(*eta, what);
        kk = spectrum_rgb(*k, what);
    } else {
        diag_.warn(eta ? eta->where : k->where, "conductor eta/k",
                   what + ": eta (" + kind_of(eta) + ") and k (" + kind_of(k) + ") are not both named metals (" + known_metal_spectra() +
                       "), both rgb or both spectra: each is reduced to RGB alone (a named metal's part from our table, a texture or one not given copper's)");
        e = conductor_part(eta, "eta", what);
        kk = conductor_part(k, "k", what);
    }
    // Our conductor takes eta > 0: a zero (or negative) index is raised to 1e-4.
    m["eta"] = rgb_json(glm::max(e, glm::dvec3(1e-4)));
    m["k"] = rgb_json(glm::max(kk, glm::dvec3(0.0)));
}

// One part of a conductor alone: a named metal's from our table, copper's (pbrt-v4's default) when
// not given or a texture (ours takes none), a named glass's index as grey, others as spectra.
glm::dvec3 MaterialTranslator::conductor_part(const std::optional<SpectrumValue>& v, const char* part, const std::string& what) {
    const bool is_eta = std::string(part) == "eta";
    std::optional<std::string> metal = metal_part(v, part);
    if (!v || v->kind == SpectrumValue::Kind::Texture) metal = "Cu";
    if (metal) {
        const NamedMetal named = *find_named_metal(*metal);
        return glm::dvec3(is_eta ? named.eta : named.k);
    }
    if (v->kind == SpectrumValue::Kind::Named)
        if (const auto glass = named_glass_ior(v->name)) return glm::dvec3(*glass);
    return spectrum_rgb(*v, what);
}

std::optional<SpectrumValue> MaterialTranslator::spectrum(const ParamList& p, const std::string& name, const std::string& what) {
    std::optional<SpectrumValue> v = p.get_spectrum(name, diag_);
    if (!v) return v;
    const std::string param = what + ": \"spectrum " + name + "\"";
    if (v->kind == SpectrumValue::Kind::Named && !is_named_spectrum(v->name)) {
        v->samples = spectrum_file(v->name, v->where, param);
        v->kind = SpectrumValue::Kind::Sampled;
    } else if (v->kind == SpectrumValue::Kind::Sampled) {
        if (const std::string why = check_spectrum_pairs(v->samples); !why.empty()) diag_.fail(v->where, param + ": " + why);
    }
    return v;
}

const std::vector<double>& MaterialTranslator::spectrum_file(const std::string& file, const Where& where, const std::string& what) {
    const std::filesystem::path path = files_.resolve(file);
    if (const auto it = spectrum_files_.find(path); it != spectrum_files_.end()) return it->second;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        const std::string metals = file.rfind("metal-", 0) == 0 ? " (the named metals: " + known_metal_spectra() + ")" : "";
        diag_.fail(where, what + ": \"" + excerpt(file) + "\" is not a named spectrum" + metals +
                              ", and no spectrum file of that name was found (looked for " + path.string() + ")");
    }
    std::string text;
    try {
        text = read_text_file(path, "spectrum file", kMaxSpectrumFileBytes);
    } catch (const InputError& e) {
        diag_.fail(where, what + ": " + e.what());
    }
    std::string error;
    std::vector<double> pairs = parse_spectrum_file(text, error);
    if (!error.empty()) diag_.fail(where, what + ": spectrum file \"" + excerpt(file) + "\": " + error);
    return spectrum_files_.emplace(path, std::move(pairs)).first->second;
}

MaterialResult MaterialTranslator::translate(const Statement& s, const std::map<std::string, MaterialResult>& named) {
    const ParamList& p = s.params;
    const std::string& type = s.type;
    const std::string what = "material \"" + excerpt(type) + "\"";
    MaterialResult out;
    json& m = out.json;
    if (type == "diffuse") {
        m = {{"type", "diffuse"}, {"albedo", colour(p, "reflectance", glm::dvec3(0.5), true, what)}};
    } else if (type == "conductor") {
        m = conductor(p, what, "");
    } else if (type == "coatedconductor") {
        diag_.warn(s.where, "coatedconductor", what + ": the clear coat is dropped: the conductor beneath alone (approximated)");
        for (const char* q : {"interface.roughness", "interface.uroughness", "interface.vroughness", "interface.eta", "thickness",
                              "albedo", "g", "maxdepth", "nsamples"})
            p.find(q);
        m = conductor(p, what, "conductor.");
    } else if (type == "dielectric" || type == "thindielectric") {
        const double eta = ior(p, "eta", what);
        if (!(eta > 0.0)) diag_.fail(s.where, what + ": \"eta\" must be > 0");
        if (type == "thindielectric") {
            m = {{"type", "thin_dielectric"}, {"ior", eta}};
        } else {
            const json r = roughness(p, what);
            if (r.is_number() && r.get<double>() == 0.0) m = {{"type", "dielectric"}, {"ior", eta}};
            else m = {{"type", "rough_dielectric"}, {"ior", eta}, {"roughness", r}};
        }
    } else if (type == "coateddiffuse") {
        double eta = ior(p, "eta", what);
        if (eta < 1.0) {
            diag_.warn(s.where, "coat eta below 1", what + ": a coat \"eta\" below 1 is raised to 1");
            eta = 1.0;
        }
        m = {{"type", "coated_diffuse"}, {"albedo", colour(p, "reflectance", glm::dvec3(0.5), true, what)}, {"ior", eta},
             {"roughness", roughness(p, what)}};
        if (p.has("albedo") || p.has("thickness") || p.has("g"))
            diag_.warn(s.where, "coateddiffuse medium", what + ": the layer's \"albedo\", \"thickness\" and \"g\" are not modelled (a clear, thin coat)");
        for (const char* q : {"albedo", "thickness", "g", "maxdepth", "nsamples"}) p.find(q);
    } else if (type == "diffusetransmission") {
        const double scale = p.get_float("scale", 1.0, diag_);
        json r = colour(p, "reflectance", glm::dvec3(0.25), true, what);
        if (r.is_array()) r = json::array({std::min(1.0, r[0].get<double>() * scale), std::min(1.0, r[1].get<double>() * scale), std::min(1.0, r[2].get<double>() * scale)});
        json t = colour(p, "transmittance", glm::dvec3(0.25), true, what);
        if (!t.is_array()) {
            diag_.warn(s.where, "transmittance texture", what + ": a \"transmittance\" texture is not supported (pbrt's default 0.25 used)");
            t = json::array({0.25, 0.25, 0.25});
        }
        t = json::array({std::min(1.0, t[0].get<double>() * scale), std::min(1.0, t[1].get<double>() * scale), std::min(1.0, t[2].get<double>() * scale)});
        m = {{"type", "diffuse"}, {"albedo", r}, {"transmittance", t}};
    } else if (type == "interface") {
        out.invisible = true;
        m = {{"type", "diffuse"}};
    } else if (type == "mix") {
        const std::vector<std::string> names = p.get_strings("materials", diag_);
        if (names.size() != 2) diag_.fail(s.where, what + ": needs \"string materials\" [ \"a\" \"b\" ] naming two materials");
        std::string tex;
        const double amount = p.get_float_or_texture("amount", tex, diag_).value_or(0.5);
        const std::string& chosen = (!tex.empty() || amount < 0.5) ? names[0] : names[1];
        const auto it = named.find(chosen);
        if (it == named.end()) diag_.fail(s.where, what + ": no material named \"" + excerpt(chosen) + "\" (define it with MakeNamedMaterial first)");
        diag_.warn(s.where, "mix", what + ": a mix is approximated by the material of the larger weight (\"" + excerpt(chosen) + "\")");
        out = it->second;
    } else {
        diag_.warn(s.where, "material " + type, "material type \"" + excerpt(type) + "\" is not supported (diffuse 0.5 instead)");
        for (const Param& q : p.params) q.used = true;
        m = {{"type", "diffuse"}, {"albedo", rgb_json(glm::dvec3(0.5))}};
    }
    // pbrt-v4's bump and normal maps, on any material, are ours (scenes/README.md, "Textures"):
    // a displacement texture is the height in world units along the shading normal (bump_scale 1),
    // a normal map an image read as linear data, as pbrt-v4 reads it.
    {
        std::string tex;
        p.get_float_or_texture("displacement", tex, diag_);  // a constant displacement tilts nothing
        if (!tex.empty()) {
            const auto it = float_textures_.find(tex);
            if (it == float_textures_.end())
                diag_.fail(s.where, what + ": \"displacement\": no float texture named \"" + excerpt(tex) + "\" (define it with Texture before the material)");
            if (it->second.is_object() && it->second.contains("image")) m["bump_map"] = it->second;
            else if (it->second.is_object())
                diag_.warn(s.where, "displacement pattern", what + ": a \"displacement\" that is not an image (a checker has no slope to bump with) is ignored");
        }
    }
    if (const std::string normal_map = p.get_string("normalmap", "", diag_); !normal_map.empty()) {
        if (const std::string problem = file_kind_problem(files_.resolve(normal_map)); !problem.empty())
            diag_.fail(s.where, what + ": \"normalmap\" image \"" + excerpt(normal_map) + "\" " + problem + " (looked for " + files_.resolve(normal_map).string() + ")");
        json image{{"file", files_.json_path(normal_map)}};
        m["normal_map"] = {{"image", image}};
    }
    p.warn_unused(what, diag_);
    return out;
}

}  // namespace sweeptrace::pbrt

// pbrt-v4 materials as ours (the material half of MaterialTranslator; textures: pbrt_textures.cpp).
#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/pbrt_materials.hpp"
#include "raytracer/scene/pbrt_spectra.hpp"

namespace sweeptrace::pbrt {

using nlohmann::json;

json rgb_json(const glm::dvec3& c) { return json::array({c.r, c.g, c.b}); }

namespace {

}  // namespace

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
    const std::optional<SpectrumValue> v = p.get_spectrum(name, diag_);
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
    const std::optional<SpectrumValue> refl = p.get_spectrum("reflectance", diag_);
    const std::optional<SpectrumValue> eta = p.get_spectrum(prefix + "eta", diag_);
    const std::optional<SpectrumValue> k = p.get_spectrum(prefix + "k", diag_);
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
        auto metal_of = [&](const std::optional<SpectrumValue>& v, const char* part) -> std::optional<std::string> {
            std::string got;
            if (!v || v->kind != SpectrumValue::Kind::Named) return std::nullopt;
            auto metal = named_metal(v->name, got);
            return metal && got == part ? metal : std::nullopt;
        };
        auto plain = [](const std::optional<SpectrumValue>& v) {
            return v && (v->kind == SpectrumValue::Kind::Rgb || v->kind == SpectrumValue::Kind::Sampled ||
                         v->kind == SpectrumValue::Kind::Blackbody);
        };
        const auto eta_metal = metal_of(eta, "eta"), k_metal = metal_of(k, "k");
        if (!eta && !k) {
            m["metal"] = "Cu";  // pbrt-v4's default: metal-Cu-eta, metal-Cu-k
        } else if (eta_metal && k_metal) {
            if (*eta_metal != *k_metal)
                diag_.warn(eta->where, "mixed metals", what + ": eta of " + *eta_metal + " with k of " + *k_metal +
                                                           ": our named metal " + *eta_metal + " is used for both");
            m["metal"] = *eta_metal;
        } else if (plain(eta) && plain(k)) {
            // Our conductor takes eta > 0: a zero (or negative) index is raised to 1e-4.
            m["eta"] = rgb_json(glm::max(spectrum_rgb(*eta, what), glm::dvec3(1e-4)));
            m["k"] = rgb_json(glm::max(spectrum_rgb(*k, what), glm::dvec3(0.0)));
        } else {
            const Where at = eta ? eta->where : k->where;
            diag_.warn(at, "conductor eta/k", what + ": eta and k must both be rgb/sampled or both named metal spectra (known metals: " +
                                                  known_metal_spectra() + "); copper (pbrt-v4's default) is used");
            m["metal"] = eta_metal ? *eta_metal : k_metal ? *k_metal : std::string("Cu");
        }
    }
    m["roughness"] = roughness(p, what, prefix);
    return m;
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
        diag_.warn(s.where, "diffusetransmission", what + ": the transmitted part is dropped: diffuse reflection only (approximated)");
        p.find("transmittance");
        m = {{"type", "diffuse"}, {"albedo", r}};
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
    if (p.has("displacement")) {
        p.find("displacement");
        diag_.warn(s.where, "displacement", what + ": \"displacement\" is not supported (ignored)");
    }
    if (p.has("normalmap")) {
        p.find("normalmap");
        diag_.warn(s.where, "normalmap", what + ": \"normalmap\" is not supported (ignored)");
    }
    p.warn_unused(what, diag_);
    return out;
}

}  // namespace sweeptrace::pbrt

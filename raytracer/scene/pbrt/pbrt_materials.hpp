#pragma once
// pbrt-v4 materials and textures -> our scene JSON's materials and textured parameters
// (scenes/README.md "Materials", "Textures"). The mapping, parameter by parameter, and what is
// approximated: docs/pbrt-import.md. Roughness is converted exactly: pbrt-v4's GGX alpha is
// sqrt(roughness) with "remaproughness" true (its default) and roughness itself otherwise; ours is
// alpha = roughness^2 (render/materials/bsdf.cpp), so our roughness = sqrt(alpha).
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "raytracer/scene/pbrt/pbrt_conductor_fit.hpp"
#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt/pbrt_scene.hpp"

namespace sweeptrace::pbrt {

// An RGB triple as our JSON writes colours: [r, g, b].
nlohmann::json rgb_json(const glm::dvec3& c);

// A file named in the scene: resolved from the main file's folder (as pbrt-v4 resolves every
// relative name), written relative to the output's folder.
class FileNames {
public:
    FileNames(const std::filesystem::path& main_file, const std::filesystem::path& output_dir);
    std::filesystem::path resolve(const std::string& name) const;  // the file itself
    std::string json_path(const std::string& name) const;          // what the JSON says

private:
    std::filesystem::path base_, out_;
};

struct MaterialResult {
    nlohmann::json json;
    bool invisible = false;  // pbrt's "interface": marks a medium boundary, scatters nothing
};

class MaterialTranslator {
public:
    MaterialTranslator(const FileNames& files, Diagnostics& diag) : files_(files), diag_(diag) {}

    // `Texture "name" "float"|"spectrum" "class" params...`
    void define_texture(const std::string& name, const std::string& kind, const Statement& s);

    // `Material "type" ...` or a MakeNamedMaterial's ("string type" read here); `named` holds the
    // materials defined so far, for "mix".
    MaterialResult translate(const Statement& s, const std::map<std::string, MaterialResult>& named);

    // A colour parameter (spectrum, rgb, texture) as our JSON value: [r, g, b] or a texture node.
    // `albedo` clamps to [0, 1] with a warning.
    nlohmann::json colour(const ParamList& p, const std::string& name, const glm::dvec3& fallback, bool albedo,
                          const std::string& what);
    // An emitted spectrum (light "L", "I") as rgb: illuminants, blackbody, rgb.
    glm::dvec3 emitted(const ParamList& p, const std::string& name, const std::string& what);

    // A spectrum parameter as pbrt-v4 reads it: a string that is not one of its named spectra
    // (pbrt_spectra.hpp, is_named_spectrum) names a spectrum file, resolved from the main file's
    // folder and read once per file, returned as Kind::Sampled with `name` the file as written;
    // sampled pairs, inline or from a file, must have wavelengths increasing. A missing or
    // malformed file: InputError with the parameter's file:line.
    std::optional<SpectrumValue> spectrum(const ParamList& p, const std::string& name, const std::string& what);

private:
    nlohmann::json roughness(const ParamList& p, const std::string& what, const std::string& prefix = "");
    double ior(const ParamList& p, const std::string& name, const std::string& what);
    glm::dvec3 spectrum_rgb(const SpectrumValue& v, const std::string& what);
    nlohmann::json conductor(const ParamList& p, const std::string& what, const std::string& prefix);
    void conductor_eta_k(const std::optional<SpectrumValue>& eta, const std::optional<SpectrumValue>& k,
                         const std::string& what, nlohmann::json& m);
    glm::dvec3 conductor_part(const std::optional<SpectrumValue>& v, const char* part, const std::string& what);
    const std::vector<double>& spectrum_file(const std::string& file, const Where& where, const std::string& what);

    const FileNames& files_;
    Diagnostics& diag_;
    std::map<std::string, nlohmann::json> float_textures_, spectrum_textures_;
    std::map<std::filesystem::path, std::vector<double>> spectrum_files_;  // by resolved path
    std::map<std::pair<std::vector<double>, std::vector<double>>, ConductorRgb> conductor_fits_;
};

}  // namespace sweeptrace::pbrt

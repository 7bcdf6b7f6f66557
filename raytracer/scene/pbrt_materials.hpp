#pragma once
// pbrt-v4 materials and textures -> our scene JSON's materials and textured parameters
// (scenes/README.md "Materials", "Textures"). The mapping, parameter by parameter, and what is
// approximated: docs/pbrt-import.md. Roughness is converted exactly: pbrt-v4's GGX alpha is
// sqrt(roughness) with "remaproughness" true (its default) and roughness itself otherwise; ours is
// alpha = roughness^2 (render/bsdf.cpp), so our roughness = sqrt(alpha).
#include <filesystem>
#include <map>
#include <string>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "raytracer/scene/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt_scene.hpp"

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

private:
    nlohmann::json roughness(const ParamList& p, const std::string& what, const std::string& prefix = "");
    double ior(const ParamList& p, const std::string& name, const std::string& what);
    glm::dvec3 spectrum_rgb(const SpectrumValue& v, const std::string& what);
    nlohmann::json conductor(const ParamList& p, const std::string& what, const std::string& prefix);

    const FileNames& files_;
    Diagnostics& diag_;
    std::map<std::string, nlohmann::json> float_textures_, spectrum_textures_;
};

}  // namespace sweeptrace::pbrt

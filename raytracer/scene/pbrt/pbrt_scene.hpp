#pragma once
// What the pbrt parser hands the JSON writer: each statement that makes something (camera, film,
// a shape, a light), with the transformation matrix and attributes in force where it was written,
// and the materials and textures already translated to our JSON (they do not depend on where they
// are used). Shapes are kept here and written after the whole file is read, so that a
// NamedMaterial may come before its MakeNamedMaterial, as pbrt-v4 allows.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt/pbrt_params.hpp"

namespace sweeptrace::pbrt {

// pbrt files give angles in degrees; the importer converts in double (geometry/warps.hpp's kPi is
// the renderer's float one).
inline constexpr double kPi = 3.14159265358979323846;

// A directive with a type name and parameters: `Shape "sphere" "float radius" 2`.
struct Statement {
    std::string type;
    ParamList params;
    Where where;
};

struct AreaLight {
    Statement statement;
};

struct ShapeRecord {
    Statement statement;
    glm::dmat4 ctm{1.0};  // object to world
    bool reverse_orientation = false;
    std::string material;  // a key of PbrtScene::materials
    // Shared, not copied: every Shape, AttributeBegin level and ObjectInstance under one
    // AreaLightSource holds the same statement, so a large parameter costs once (issue 32).
    std::shared_ptr<const AreaLight> area_light;
    // Its MediumInterface: media names, "" vacuum (after the parse: names of supported media
    // only, PbrtScene::media; an unsupported medium's name has become "").
    std::string inside, outside;
};

struct LightRecord {
    Statement statement;
    glm::dmat4 ctm{1.0};
};

struct PbrtScene {
    std::filesystem::path main_file;  // relative file names resolve from its folder (as pbrt-v4 does)
    std::optional<Statement> camera, film, sampler, filter, integrator;
    glm::dmat4 camera_from_world{1.0};
    std::vector<ShapeRecord> shapes;
    std::vector<LightRecord> lights;
    std::map<std::string, nlohmann::json> materials;  // our JSON material by its name in the output
    std::map<std::string, Where> material_where;      // the statement that defined it, for messages
    // Materials that make a shape invisible to light (pbrt's "interface"): shapes using one are left out.
    std::map<std::string, bool> invisible;
    // MakeNamedMedium's media as our JSON (pbrt_media.hpp), by name, and the camera's (the
    // MediumInterface's outside medium where Camera was given; "" vacuum).
    std::map<std::string, nlohmann::json> media;
    std::map<std::string, Where> medium_where;  // the MakeNamedMedium that defined it, for messages
    std::string camera_medium;
};

}  // namespace sweeptrace::pbrt

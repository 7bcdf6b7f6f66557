#pragma once
// The JSON loader's entry for a document already in memory (the pbrt importer's output): the
// same reading and checks as load_scene (load_scene.hpp), with `file` standing for the document in
// messages and as the folder relative file names resolve from. Internal to scene/: it exposes
// nlohmann::json.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

Scene load_scene_document(const nlohmann::json& doc, const std::filesystem::path& file);

}  // namespace sweeptrace

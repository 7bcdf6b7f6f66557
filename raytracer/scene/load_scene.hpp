#pragma once
// JSON scene file → validated Scene. The format is documented in scenes/README.md.
#include <filesystem>

#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// Reads and validates `file`; OBJ meshes are resolved relative to the scene file's directory and
// loaded once per distinct file. Every problem throws InputError whose message starts with the
// file and says where: `scene.json: objects[3].radius: must be > 0, got -1`, or line:column for
// text that is not JSON. Unknown keys, shapes and material types are errors, not ignored.
Scene load_scene(const std::filesystem::path& file);

}  // namespace sweeptrace

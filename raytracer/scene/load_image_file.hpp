#pragma once
// An image a scene key names (an environment map, a texture), loaded; internal to the loader.
#include <memory>
#include <string>

#include "raytracer/image/image.hpp"
#include "raytracer/scene/json_reader.hpp"

namespace sweeptrace {

// `file` is the key's string node, a path relative to the scene file's folder; `what` names
// the image in messages ("environment image", "texture image"). Fails at `file` when the
// string is empty, the file is missing or unreadable, or the image is empty.
std::shared_ptr<const Image> read_image_file(const scene_json::Node& file, const std::string& what);

}  // namespace sweeptrace

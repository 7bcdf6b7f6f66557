#pragma once
// An image a scene key names (an environment map, a texture), loaded; internal to the loader.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "raytracer/image/image.hpp"
#include "raytracer/scene/json_reader.hpp"

namespace sweeptrace {

// Called with a message when the image cannot be used; must not return (it throws).
using ImageFail = std::function<void(const std::string&)>;

// `file` is the key's string node, a path relative to the scene file's folder; `what` names
// the image in messages ("environment image", "texture image"). Fails at `file` when the
// string is empty, the file is missing or unreadable, or the image is empty.
std::shared_ptr<const Image> read_image_file(const scene_json::Node& file, const std::string& what);

// The same for an image another file names (an .mtl's map_Kd): `relative` as written there,
// `path` where it was looked for; failures go to `fail`.
std::shared_ptr<const Image> read_image_path(const std::string& relative, const std::filesystem::path& path,
                                             const std::string& what, const ImageFail& fail);

}  // namespace sweeptrace

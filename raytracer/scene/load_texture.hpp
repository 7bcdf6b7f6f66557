#pragma once
// Texture keys (a colour given as an object instead of [r, g, b]), validated and loaded; and the
// check that every textured object's shape has uv coordinates. Internal to the scene loader.
#include <vector>

#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// `node` is {"checker": {"a": [..], "b": [..], "scale": n}} or {"image": {"file": .., "wrap": ..}};
// image files are relative to the scene file's folder. An image file that one of `loaded`
// already holds is shared, not read again.
Texture read_texture(const scene_json::Node& node, const std::vector<Texture>& loaded);

// Fails at objects[i].material when an object's material reads a texture but its shape's home
// defines no uv (geometry/shapes/, `uv`).
void check_texture_uv(const Scene& scene, const scene_json::Node& objects);

}  // namespace sweeptrace

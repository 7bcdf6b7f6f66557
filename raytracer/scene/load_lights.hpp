#pragma once
// The scene's "lights" key (point, spot, directional), validated; internal to the scene loader.
#include <vector>

#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene_light.hpp"

namespace sweeptrace {

// `node` is the value of "lights": an array of light objects. Every error names the JSON path.
std::vector<SceneLight> read_lights(const scene_json::Node& node);

}  // namespace sweeptrace

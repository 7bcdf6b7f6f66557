#pragma once
// The film's "filter" key, validated; internal to the scene loader.
#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// `node` is the value of film.filter: {"type": "box"|"tent"|"gaussian"|"mitchell", "radius": ...}.
FilterSpec read_filter(const scene_json::Node& node);

}  // namespace sweeptrace

#pragma once
// The film's display keys (exposure, tone_curve), validated; internal to the scene loader.
#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// `node` is the "film" object (its keys already checked against the allowed list).
void read_film_display(const scene_json::Node& node, Film& film);

}  // namespace sweeptrace

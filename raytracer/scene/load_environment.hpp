#pragma once
// The background's "environment" key, validated and its image loaded; internal to the loader.
#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// `node` is {"file": "x.hdr"|"x.exr"|"x.pfm", "rotate": degrees, "mirror": bool,
// "mapping": "equirect"|"equal-area", "scale": s}; the file is relative to the scene file's folder.
void read_environment(const scene_json::Node& node, Background& background);

}  // namespace sweeptrace

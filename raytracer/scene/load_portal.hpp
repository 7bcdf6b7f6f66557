#pragma once
// The background's "portal" key, validated; internal to the loader.
#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// `node` is [[x, y, z] x 4]: a rectangle's corners in order round its edge (render/lights/portal.hpp).
// Opposite edges must be parallel and adjacent ones perpendicular, each to within 0.001 in the
// cosine of their angle: pbrt-v4's own test of a portal, so every portal pbrt-v4 accepts loads
// here (the importer writes pbrt's corners as they are), and corners written with a few digits
// do too.
void read_portal(const scene_json::Node& node, Background& background);

}  // namespace sweeptrace

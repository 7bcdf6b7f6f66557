#pragma once
// Coordinates the renderer can hold: every object's box, in its object space and in the world,
// and the camera, within +-kMaxSceneCoordinate. Each coordinate on its own is a finite float,
// but a box built from them (center + radius, a transformed corner) may not be, and the BVH's
// surface areas and the intersectors' squared distances overflow long before FLT_MAX (3.4e38):
// a 1e20 extent squared is already infinite in float. Checked once at load, so both accelerators
// (--accel bvh and embree) see the same scenes, and the message names the object's JSON path.
//
// 1e18 leaves squares (1e36) and sums of a few of them finite in float; the largest real scene
// coordinate in the repo is smallpt's 1e5 wall radius.
#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

inline constexpr float kMaxSceneCoordinate = 1e18f;

// `root` is the scene document the Scene was read from (for the JSON paths). Throws InputError
// "<file>: objects[i]: ..." or "<file>: camera.position: ..." for the first object out of bounds.
void check_scene_extent(const Scene& scene, const scene_json::Node& root);

}  // namespace sweeptrace

#pragma once
// The scene keys of participating media (scenes/README.md, "Media"): the "media" table, an
// object's "inside" and "outside", the camera's "medium", and the "interface" material. Internal
// to the scene loader, like json_reader.hpp.
//
//   media: { "<name>": { "type": "homogeneous", "sigma_a": [r, g, b], "sigma_s": [r, g, b],
//            "scale": s, "g": g, "emission": [r, g, b] }, ... }
//     or    { "type": "grid", the same keys, and "size": [nx, ny, nz], "density": [nx ny nz
//            numbers, x fastest], "p0": [x, y, z], "p1": [x, y, z], "transform": [steps],
//            "emission_scale": [nx ny nz numbers] }
//     or    { "type": "vdb", the homogeneous keys, and "file": "smoke.vdb" (OpenVDB, or NanoVDB's
//            .nvdb; relative to the scene file), "grid": "density" (the default), "transform" }
//     (pbrt-v4's "homogeneous", "uniformgrid" and "nanovdb"; scene/medium.hpp states what they
//     mean). A "vdb" medium is a grid medium: the file's active box read densely (vdb_grid.hpp),
//     the file's index-to-world map applied after the medium's transform.
// Errors (exit 2, one line with the JSON path): a negative or non-finite sigma, scale or density
// (and a sigma times scale that overflows), |g| >= 1, a size that is not three positive integers,
// a density (or emission_scale) with another count of numbers than nx ny nz, p1 not above p0 on
// every axis, a medium name that is empty or unknown where it is used, a VDB file that is
// missing, not a VDB, corrupt or truncated, without that float grid, or too large for the budget
// (vdb_grid.hpp lists its errors; said at the medium's "file"). A grid's samples are charged to
// the load budget (load_budget.hpp) before they are copied or read.
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

using MediumIndex = std::map<std::string, std::int32_t>;

// The "media" table into scene.media; returns the index of each name. `read_transform` is the
// loader's reader of a transform list.
MediumIndex read_media(const scene_json::Node& media, Scene& scene, Transform (*read_transform)(const scene_json::Node&));

// A medium's name where it is used (an object's inside / outside, the camera's medium).
std::int32_t read_medium_name(const scene_json::Node& name, const MediumIndex& media);

// An object's "inside" and "outside" keys (either may be absent: vacuum on that side).
MediumInterface read_medium_interface(const scene_json::Node& object, const MediumIndex& media);

}  // namespace sweeptrace

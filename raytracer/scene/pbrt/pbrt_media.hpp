#pragma once
// pbrt-v4's MakeNamedMedium as our JSON "media" entry (scene/load_media.hpp states the keys):
//   "homogeneous": sigma_a, sigma_s (pbrt-v4's defaults when absent), scale, g, Le x Lescale;
//   "uniformgrid": the same coefficients, density over nx x ny x nz, p0, p1, and the current
//     transformation matrix as the medium's transform;
//   "nanovdb": our "vdb" medium: the .nvdb "filename" (resolved as pbrt-v4 resolves names), its
//     "gridname" grid (default "density"), sigma_a and sigma_s (default 1, as pbrt-v4's
//     NanoVDBMedium), scale, g, and the current transformation matrix. The file is read when the
//     scene is loaded (scene/vdb_grid.hpp); its errors are said at this statement's line.
// Other types ("cloud", "rgbgrid") and what is not modelled (a homogeneous "preset", a grid's
// "Le", a nanovdb's "temperature" grid and blackbody emission) are warned with what is lost; an
// unsupported medium returns nullopt and the importer treats its name as vacuum.
#include <optional>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt/pbrt_materials.hpp"
#include "raytracer/scene/pbrt/pbrt_scene.hpp"

namespace sweeptrace::pbrt {

// `s` is the MakeNamedMedium statement ("string type" among its parameters), `name` its name,
// `ctm` the medium-to-world matrix in force there.
std::optional<nlohmann::json> translate_medium(const Statement& s, const std::string& name, const glm::dmat4& ctm,
                                               MaterialTranslator& materials, const FileNames& files, Diagnostics& diag);

}  // namespace sweeptrace::pbrt

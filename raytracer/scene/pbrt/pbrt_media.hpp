#pragma once
// pbrt-v4's MakeNamedMedium as our JSON "media" entry (scene/load_media.hpp states the keys):
//   "homogeneous": sigma_a, sigma_s (pbrt-v4's defaults when absent), scale, g, Le x Lescale;
//   "uniformgrid": the same coefficients, density over nx x ny x nz, p0, p1, and the current
//     transformation matrix as the medium's transform.
// Other types ("nanovdb", "cloud", "rgbgrid") and what is not modelled (a homogeneous "preset", a
// grid's "Le" or "temperature") are warned with what is lost; an unsupported medium returns
// nullopt and the importer treats its name as vacuum.
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
                                               MaterialTranslator& materials, Diagnostics& diag);

}  // namespace sweeptrace::pbrt

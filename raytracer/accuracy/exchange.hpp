#pragma once
// The ray families as files, so an intersector in any language can be scored with the same
// table as the built-ins (format in docs/accuracy-for-your-intersector.md):
//   export_rays writes DIR/manifest.json and one JSON-lines file per shape and family, each line
//   a case: its id "shape/family/index", the shape, the ray and the long double reference's
//   verdict and t;
//   score_results reads a JSON-lines results file ({"case": id, "hit": bool, "t": number}) and
//   scores it exactly as run_family scores a built-in routine, regenerating the cases from the
//   same rays-per-family and seed (the families are deterministic), so nothing in the exported
//   files needs to be trusted back.
// The secondary-ray families (surface-out, surface-in) are not exported: their rays start at the
// routine's own hits; use the C++ hook (user_routines.hpp) for those. Nor is the edges family of
// triangles and quads (closed meshes, many faces per ray).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "raytracer/accuracy/run.hpp"

namespace sweeptrace::accuracy {

// Throws InputError when DIR cannot be created or written.
void export_rays(const std::filesystem::path& dir, const std::vector<std::string>& shapes, std::size_t n,
                 std::uint64_t seed);

// One row per (shape, family) present in the results; `variant` names the rows. Throws
// InputError naming the file and line on malformed lines, unknown case ids, duplicate cases, or a
// family whose results do not cover all of its cases.
std::vector<Metrics> score_results(const std::filesystem::path& results, std::size_t n, std::uint64_t seed,
                                   const std::string& variant);

}  // namespace sweeptrace::accuracy

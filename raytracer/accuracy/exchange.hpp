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
#include <ostream>
#include <string>
#include <vector>

#include "raytracer/accuracy/run.hpp"

namespace sweeptrace::accuracy {

// Throws InputError when DIR cannot be created or written.
void export_rays(const std::filesystem::path& dir, const std::vector<std::string>& shapes, std::size_t n,
                 std::uint64_t seed);

// Optional "point": [x, y, z] in results: the hit point's error relative to the distance the ray
// travelled, |p - p_ref| / (t_ref |dir|), p_ref = origin + t_ref dir in long double, over the
// cases where both the reference and the routine hit.
struct PointErrors {
    std::string shape, family;
    std::size_t scored = 0;
    double median = 0.0, p99 = 0.0, max = 0.0;
};

// One row per (shape, family) present in the results; `variant` names the rows; `points` (if
// given) receives one row per family whose results carry points. Throws
// InputError naming the file and line on malformed lines, unknown case ids, duplicate cases, or a
// family whose results do not cover all of its cases.
std::vector<Metrics> score_results(const std::filesystem::path& results, std::size_t n, std::uint64_t seed,
                                   const std::string& variant, std::vector<PointErrors>* points = nullptr);

void write_point_errors(std::ostream& out, const std::vector<PointErrors>& rows);

}  // namespace sweeptrace::accuracy

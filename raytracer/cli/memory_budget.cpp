#include "raytracer/cli/memory_budget.hpp"

#include <algorithm>

#include <glm/vec3.hpp>

#include "raytracer/image/feature_sums.hpp"
#include "raytracer/image/partial_sum.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/film/film_splats.hpp"
#include "raytracer/render/integrators/light_vertices.hpp"
#include "raytracer/render/film/path_forensics.hpp"
#include "raytracer/render/renderer.hpp"

namespace sweeptrace {

namespace {

// Per pixel: renderer sums and sums of squares (2 x dvec3), the pass in flight, the mean and the
// variance images (3 x vec3), the display copy (vec3) and the 8-bit RGB buffer plus its encoding.
constexpr std::uint64_t kFilmBytesPerPixel = 2 * 24 + 3 * 12 + 12 + 2 * 3;
// vcm keeps every pixel's light subpath of the iteration (integrators/vcm.hpp): per vertex, its
// photon and surface, its pointer in a grid cell with the table's share (light_vertices.hpp).
// Counted at max_depth vertices per pixel, the most a light subpath holds.
constexpr std::uint64_t kVcmBytesPerLightVertex = LightVertices::kBytesPerVertex;
// Adaptive sampling (render/renderer.cpp, run_adaptive): per pixel its count of samples (int) and
// weight (double), the pass in flight's sums and sums of squares, and once more those for a farm
// part whose range starts inside the pilot (its own pilot passes beside the whole pilot's).
constexpr std::uint64_t kAdaptiveBytesPerPixel = sizeof(int) + sizeof(double) + 2 * (sizeof(PixelSum) + sizeof(glm::dvec3));
// Feature outputs (film.aovs, render --aovs; image/feature_sums.hpp): per pixel the renderer's
// exact sums by half and the colours and features of the passes not yet added to them, then either
// the output's images (15 colour-sized layers and the depth variance: a PNG or PFM output's side
// files are made from them; an EXR is written from the sums a block of rows at a time, which holds
// none of them) or, for a farm part, the sums' copy and their words; the larger of those two
// counted. Adaptive sampling adds its copies of the sums (the pass in flight's, and a part's own
// pilot passes), as for the colour.
constexpr std::uint64_t kAovLayerBytesPerPixel = 15 * sizeof(glm::vec3) + sizeof(float);
constexpr std::uint64_t kAovBytesPerPixel =
    sizeof(FeatureSums) + kAovPendingPasses * sizeof(FeatureSample) +
    std::max<std::uint64_t>(kAovLayerBytesPerPixel, sizeof(FeatureSums) + kFeatureWords * sizeof(std::uint32_t));
// merge with feature outputs: the whole's feature sums, the part's and its words, and the images
// (a PNG or PFM output's; counted for any).
constexpr std::uint64_t kAovMergeBytesPerPixel =
    2 * sizeof(FeatureSums) + kFeatureWords * sizeof(std::uint32_t) + kAovLayerBytesPerPixel;
constexpr std::uint64_t kAovAdaptiveBytesPerPixel = 2 * sizeof(FeatureSums);
// Per primitive of the acceleration structure (a triangle, or an analytic object at the top
// level): BVH nodes (~2 per primitive at 32 bytes), the primitive's index and precomputed test
// data, and the builder's temporary boxes and centroids. Rounded up: Embree's is of that order.
constexpr std::uint64_t kAccelBytesPerPrimitive = 256;
// Per mesh vertex kept in the acceleration structure's own copy (position + normal).
constexpr std::uint64_t kAccelBytesPerVertex = 24;

}  // namespace

MemoryEstimate estimate_render_memory(const Scene& scene, bool adaptive, bool forensics) {
    MemoryEstimate e;
    const std::uint64_t pixels = std::uint64_t(scene.film.width) * std::uint64_t(scene.film.height);
    e.film = pixels * kFilmBytesPerPixel;
    if (scene.film.integrator == IntegratorKind::Vcm)
        e.film += pixels * std::uint64_t(scene.film.max_depth) * kVcmBytesPerLightVertex;
    if (adaptive) e.film += pixels * kAdaptiveBytesPerPixel;
    if (scene.film.aovs) e.film += pixels * (kAovBytesPerPixel + (adaptive ? kAovAdaptiveBytesPerPixel : 0));
    if (scene.film.integrator != IntegratorKind::Path)
        e.splats = splat_buffer_bytes(scene.film.width, scene.film.height, scene.film.max_depth);
    if (forensics) e.forensics = PathForensics::memory_bytes(scene.film.width, scene.film.height);
    std::uint64_t primitives = scene.objects.size(), vertices = 0;
    for (const Mesh& m : scene.meshes) {
        primitives += m.triangles.indices.size();
        vertices += m.triangles.vertices.size();
    }
    e.scene = primitives * kAccelBytesPerPrimitive + vertices * kAccelBytesPerVertex;
    return e;
}

void check_memory_estimate(std::uint64_t bytes, std::optional<std::uint64_t> limit, const std::string& what,
                           const std::string& detail) {
    const std::optional<std::uint64_t> room = limit ? limit : available_memory();
    if (!room || bytes <= *room) return;
    throw InputError(what + " needs an estimated " + byte_text(bytes) + " (" + detail + "), more than the " +
                     byte_text(*room) +
                     (limit ? " that --max-memory allows" : " of memory available (--max-memory sets the limit)"));
}

void check_render_memory(const Scene& scene, std::optional<std::uint64_t> limit, bool adaptive, bool forensics) {
    const MemoryEstimate e = estimate_render_memory(scene, adaptive, forensics);
    std::string detail = "film " + std::to_string(scene.film.width) + "x" + std::to_string(scene.film.height) + ": " +
                         byte_text(e.film);
    if (e.splats > 0)
        detail += ", light splats at depth " + std::to_string(scene.film.max_depth) + ": " + byte_text(e.splats);
    if (e.forensics > 0) detail += ", --forensics: " + byte_text(e.forensics);
    check_memory_estimate(e.total(), limit, scene.source.string() + ": the render", detail + ", scene: " + byte_text(e.scene));
}

void check_merge_memory(int width, int height, bool adaptive, bool aovs, const std::string& part) {
    const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
    const std::uint64_t counts = adaptive ? 3 * sizeof(int) : 0;  // the whole's, the part's words and its ints
    const std::uint64_t per_pixel = 2 * sizeof(PixelSum) + 12 * sizeof(std::uint32_t) + counts + 2 * sizeof(glm::vec3) + 3 +
                                    (aovs ? kAovMergeBytesPerPixel : 0);
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    std::optional<std::uint64_t> none;
    check_memory_estimate(pixels * per_pixel, none, "'" + part + "': merging parts of " + size,
                          std::to_string(per_pixel) + " bytes a pixel");
}

}  // namespace sweeptrace

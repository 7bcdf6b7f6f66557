#pragma once
// The memory a render will take, estimated before anything large is allocated, and refused with
// the estimate when it exceeds what the machine has (or --max-memory): a film within the scene
// limits (16384 x 16384) needs ~27 GB, which would otherwise end in bad_alloc or the OOM killer
// after minutes.
//
// The estimate counts the big allocations, each per element with its size in memory_budget.cpp:
// the film (the renderer's double-precision sums, the pass buffer, the mean and variance images,
// the display copy and the encoded file; under vcm also every pixel's light subpath, under
// adaptive sampling its per-pixel counts, weights and pass sums, with feature outputs (film.aovs)
// their exact sums and images), bdpt's and vcm's light-tracing splat buffers (bounded by the
// renderer's waves, render/film/film_splats.hpp), --forensics' per-region sums
// (render/film/path_forensics.hpp) and the scene's acceleration structure over every object and
// triangle. It is an estimate of the peak, not a bound: small per-object data and
// allocator overhead are not counted. The scene's meshes are already loaded when it is made
// (their input files are limited in size, scene/text_file.hpp) and are not part of it.
#include <cstdint>
#include <optional>
#include <string>

#include "raytracer/load_budget.hpp"  // available_memory, byte_text
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

struct MemoryEstimate {
    std::uint64_t film = 0;
    std::uint64_t splats = 0;     // bdpt, vcm: the light-tracing splats of a wave of tiles
    std::uint64_t forensics = 0;  // render --forensics
    std::uint64_t scene = 0;
    std::uint64_t total() const { return film + splats + forensics + scene; }
};

// `adaptive`: render --adaptive on|relative; `forensics`: render --forensics (render options,
// not the scene's).
MemoryEstimate estimate_render_memory(const Scene& scene, bool adaptive = false, bool forensics = false);

// Throws InputError "render needs an estimated X (film WxH: A, light splats: S, forensics: F,
// scene: B), more than the Y available ..." (the splats and forensics when counted) when the
// estimate exceeds `limit` (from --max-memory) or, without one, the available memory.
void check_render_memory(const Scene& scene, std::optional<std::uint64_t> limit, bool adaptive = false,
                         bool forensics = false);

// `merge`: the parts' sums and counts for the whole image, one part being read (its 32-bit words,
// sums and counts), the mean image and its display copy, per pixel of the parts' WxH; with
// feature outputs (`aovs`) their sums likewise and the feature images. Throws InputError naming
// `part` (the file that declared the size) when over the available memory.
void check_merge_memory(int width, int height, bool adaptive, bool aovs, const std::string& part);

// Throws InputError "<what> needs an estimated X (<detail>), more than the Y ..." when `bytes`
// exceed `limit` or, without one, the available memory: the one refusal of the estimates above,
// for a command's own estimate (reference-check's).
void check_memory_estimate(std::uint64_t bytes, std::optional<std::uint64_t> limit, const std::string& what,
                           const std::string& detail);

}  // namespace sweeptrace

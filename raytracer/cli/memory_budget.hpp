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
// their exact sums and images) and the
// scene's acceleration structure over every
// object and triangle. It is an estimate of the peak, not a bound: small per-object data and
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
    std::uint64_t scene = 0;
    std::uint64_t total() const { return film + scene; }
};

// `adaptive`: render --adaptive on|relative (a render option, not the scene's).
MemoryEstimate estimate_render_memory(const Scene& scene, bool adaptive = false);

// Throws InputError "render needs an estimated X (film WxH: A, scene: B), more than the Y
// available ..." when the estimate exceeds `limit` (from --max-memory) or, without one, the
// available memory.
void check_render_memory(const Scene& scene, std::optional<std::uint64_t> limit, bool adaptive = false);

}  // namespace sweeptrace

#pragma once
// The render's command-line numbers (--width, --height, --spp, --max-depth, --seed, --threads,
// --max-memory), read as text and checked here rather than by CLI11, so that each gets the same
// range as the scene file's value it overrides (scene/film_limits.hpp), "-1" is not wrapped to a
// huge unsigned seed, and every refusal is one `sweeptrace: error:` line naming the option.
#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// More worker threads than this is a typo, not a machine: each costs a stack, and TBB was seen
// to crash creating 100000.
inline constexpr std::int64_t kMaxThreads = 1024;

struct RenderLimits {
    std::string width, height, spp, max_depth, seed, threads = "0", max_memory;
    CLI::Option *width_opt = nullptr, *height_opt = nullptr, *spp_opt = nullptr, *depth_opt = nullptr,
                *seed_opt = nullptr, *memory_opt = nullptr;

    // Registers the options on `cmd`.
    void add_options(CLI::App& cmd);
    // Throws InputError for any malformed or out-of-range value given (before the scene is read).
    void validate() const;
    // Overrides the scene's film and seed with what was given; --width or --height alone keeps
    // the film's aspect ratio (the derived side must be in range too). Throws InputError.
    void apply(Scene& scene) const;
    int thread_count() const;                        // 0 = all cores
    std::optional<std::uint64_t> memory_limit() const;  // --max-memory in bytes, if given
};

// "4G", "512M", "1.5G", "800k" or a plain byte count; nullopt when not a size.
std::optional<std::uint64_t> parse_byte_size(const std::string& text);

}  // namespace sweeptrace

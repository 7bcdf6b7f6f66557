#pragma once
// The renderer's tiles: squares of kRenderTileSize pixels, in rows from the top left. The unit of
// a pass's parallel work (renderer.cpp), of the waves its light-tracing splats are added in
// (film_splats.hpp) and of the noise forensics' regions (path_forensics.hpp); the render's memory
// estimate (cli/memory_budget.cpp) counts by them too, so the size has this one home.
#include <cstdint>

namespace sweeptrace {

inline constexpr int kRenderTileSize = 16;

inline std::uint64_t render_tile_count(int width, int height) {
    const auto across = [](int n) { return static_cast<std::uint64_t>((n + kRenderTileSize - 1) / kRenderTileSize); };
    return across(width) * across(height);
}

}  // namespace sweeptrace

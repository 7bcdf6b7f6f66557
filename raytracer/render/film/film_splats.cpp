#include "raytracer/render/film/film_splats.hpp"

#include "raytracer/render/render_tiles.hpp"

namespace sweeptrace {

std::uint64_t splat_buffer_bytes(int width, int height, int max_depth) {
    const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
    const std::uint64_t wave = std::uint64_t(kSplatWaveTiles) * kRenderTileSize * kRenderTileSize;
    return pixels * sizeof(glm::vec3) + std::min(pixels, wave) * std::uint64_t(max_depth) * sizeof(Splat) * 2;
}

}  // namespace sweeptrace

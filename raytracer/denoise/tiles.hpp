#pragma once
// The denoiser's unit of parallel work: square tiles of the image, each computed by one task from
// its inputs alone, so the result does not depend on how many threads run them. Every task runs
// with subnormals flushed (subnormals.hpp), whichever thread takes it.
#include <algorithm>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raytracer/denoise/planes.hpp"
#include "raytracer/denoise/subnormals.hpp"

namespace sweeptrace::denoise {

// 32 pixels: a tile's working buffers (a few channels of (32 + 2 * patch radius)^2 floats per
// offset) stay in the core's cache, and a 320x180 image still has 60 tiles for the threads.
inline constexpr int kTileSize = 32;

// NL-means' tiles (nl_means.cpp) are wider: its buffers per tile are a few channels of one offset,
// so 64 pixels still fit the core's L2 (about 0.3 MB with seven channels), and each offset's
// pixel distances are computed over the tile grown by the patch radius, 70^2 / 64^2 = 1.2 times
// the tile's pixels for 7x7 patches instead of 38^2 / 32^2 = 1.41; the rows of 64 are also four
// vectors of AVX-512 per loop instead of two. A pixel's result does not depend on its tile (its
// sums run over the offsets and the patch in one fixed order), so the bits are those of 32.
inline constexpr int kNlMeansTileSize = 64;

inline std::vector<Rect> image_tiles(int width, int height, int size = kTileSize) {
    std::vector<Rect> tiles;
    for (int y = 0; y < height; y += size)
        for (int x = 0; x < width; x += size)
            tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
    return tiles;
}

// Calls work(begin, end) on chunks of [0, n) in parallel: for whole-image loops whose every element
// (a pixel, or a row) is computed from the inputs alone, so the result does not depend on the
// chunks (serial, such a loop over a 1920x1080 image kept one of two cores idle).
template <class Work>
void for_each_chunk(std::size_t n, std::size_t grain, const Work& work) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain), [&](const tbb::blocked_range<std::size_t>& r) {
        const SubnormalsFlushed flushed;
        work(r.begin(), r.end());
    });
}

// Calls work(tile_index, tile) for every tile, in parallel (the caller's tbb::task_arena sets the
// threads); `work` must write only what belongs to its tile.
template <class Work>
void for_each_tile(const std::vector<Rect>& tiles, const Work& work) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
        const SubnormalsFlushed flushed;
        for (std::size_t i = r.begin(); i != r.end(); ++i) work(i, tiles[i]);
    });
}

}  // namespace sweeptrace::denoise

#pragma once
// Light tracing's contributions to the film: bdpt's and vcm's t = 1 strategy (integrators/bdpt.hpp)
// joins a light vertex to the lens and lands on a film position, whose value every pixel the pixel
// filter reaches there shares. A splat is kept as that position and value, one per light vertex,
// and spread over the pixels only when the renderer adds it to the pass in flight
// (SplatFootprint). Kept spread, one splat was one entry per pixel of the filter's footprint:
// (2 r)^2 = 1024 of them for a Gaussian of radius 16, 3 GB for one 640x640 bdpt pass.
//
// The renderer adds a pass's splats in waves of kSplatWaveTiles tiles (renderer.cpp, run_tiles)
// to a per-pixel sum of the pass's splats, so its buffers hold one wave's splats at a time
// whatever the image's size: at most max_depth per sample (a light subpath has at most max_depth
// vertices, each joined to the lens once), which splat_buffer_bytes charges to the memory
// estimate with the per-pixel sum.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raytracer/render/film/pixel_filter.hpp"

namespace sweeptrace {

struct Splat {
    glm::vec2 film{0.0f};     // where it lands, in pixels from the film's top-left corner
    glm::vec3 value{0.0f};  // before the filter's weight
};

// The pixels a splat reaches and their weights: f(dx) f(dy) / (int f)^2 for the pixel centre at
// (dx, dy) from the splat, what a camera sample of that pixel estimates (bdpt.hpp).
class SplatFootprint {
public:
    SplatFootprint(const PixelFilter& filter, float radius, int width, int height)
        : filter_(filter), radius_(radius), width_(width), height_(height),
          norm_(1.0 / (filter.integral() * filter.integral())) {}

    // add(pixel, weighted value) for every pixel whose filter reaches the splat, row by row: the
    // same pixels and values, in the same order, for the same splat. One caller at a time (the
    // columns' weights are computed once per splat into a buffer kept here).
    template <class Add>
    void spread(const Splat& s, Add&& add) {
        const float fx = s.film.x, fy = s.film.y;
        const int x0 = std::max(0, static_cast<int>(std::ceil(fx - radius_ - 0.5f)));
        const int x1 = std::min(width_ - 1, static_cast<int>(std::floor(fx + radius_ - 0.5f)));
        const int y0 = std::max(0, static_cast<int>(std::ceil(fy - radius_ - 0.5f)));
        const int y1 = std::min(height_ - 1, static_cast<int>(std::floor(fy + radius_ - 0.5f)));
        if (x1 < x0) return;
        columns_.resize(static_cast<std::size_t>(x1 - x0 + 1));
        for (int px = x0; px <= x1; ++px) columns_[static_cast<std::size_t>(px - x0)] = weight(double(fx) - (px + 0.5));
        for (int py = y0; py <= y1; ++py) {
            const double wy = weight(double(fy) - (py + 0.5));
            if (wy == 0.0) continue;
            for (int px = x0; px <= x1; ++px) {
                const double wx = columns_[static_cast<std::size_t>(px - x0)];
                if (wx == 0.0) continue;
                add(static_cast<std::size_t>(py) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(px),
                    s.value * static_cast<float>(wx * wy * norm_));
            }
        }
    }

private:
    const PixelFilter& filter_;
    float radius_;
    int width_, height_;
    double norm_;
    std::vector<double> columns_;

    double weight(double d) const { return std::abs(d) < radius_ ? filter_.eval(d) : 0.0; }  // the support, half-open
};

// Tiles whose splats the renderer holds at once: 64 tiles of 16x16 pixels. Fewer waves keep the
// threads busier between the wave's serial additions; smaller ones bound the buffers tighter.
inline constexpr int kSplatWaveTiles = 64;

// The splat buffers of a width x height render at most: the pass's per-pixel sum (a vec3), and one
// wave's samples, max_depth splats each, twice for the vectors' growth (a vector's capacity is
// under twice the most it held).
std::uint64_t splat_buffer_bytes(int width, int height, int max_depth);

}  // namespace sweeptrace

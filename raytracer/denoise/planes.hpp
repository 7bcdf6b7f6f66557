#pragma once
// A float image of any number of channels, stored channel by channel (planar): the denoiser's
// working buffers, whose filters run over one channel of many pixels at a time.
#include <cstddef>
#include <vector>

namespace sweeptrace::denoise {

struct Planes {
    int width = 0, height = 0, channels = 0;
    std::vector<float> data;  // channel c's pixel (x, y) at (c * height + y) * width + x

    Planes() = default;
    Planes(int w, int h, int c) : width(w), height(h), channels(c), data(std::size_t(w) * std::size_t(h) * std::size_t(c), 0.0f) {}

    std::size_t pixels() const { return std::size_t(width) * std::size_t(height); }
    float* channel(int c) { return data.data() + std::size_t(c) * pixels(); }
    const float* channel(int c) const { return data.data() + std::size_t(c) * pixels(); }
    float& at(int c, int x, int y) { return channel(c)[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    float at(int c, int x, int y) const { return channel(c)[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// A half-open pixel rectangle [x0, x1) x [y0, y1).
struct Rect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
};

}  // namespace sweeptrace::denoise

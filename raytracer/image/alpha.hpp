#pragma once
// The alpha channel of an image file, which read_image drops, so that `diff` can compare it and
// composite colour over a stated background instead of silently ignoring it.
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/image/image.hpp"

namespace sweeptrace {

struct AlphaChannel {
    std::vector<float> values;   // per pixel, row-major; empty when the file has no alpha
    bool premultiplied = false;  // EXR colour is premultiplied by convention, PNG colour is not
    bool present() const { return !values.empty(); }
};

// PNG (8/16-bit, grey+alpha or RGBA) and EXR ("A" channel); PFM holds no alpha.
// Throws InputError naming the file when it cannot be read.
AlphaChannel read_alpha(const std::filesystem::path& path);

// Linear colour over a linear background: c a + bg (1 - a), or c + bg (1 - a) when premultiplied.
// No alpha: the image unchanged.
Image composite_over(const Image& image, const AlphaChannel& alpha, const glm::vec3& background);

}  // namespace sweeptrace

namespace sweeptrace {

// An EXR with R, G, B (premultiplied, as EXR expects) and A, written atomically like write_image.
void write_exr_with_alpha(const Image& premultiplied, const std::vector<float>& alpha, const std::filesystem::path& path);

}  // namespace sweeptrace

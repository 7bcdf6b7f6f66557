#pragma once
// The display transform applied before writing an 8-bit image: radiance times `exposure`,
// clamped to [0, 1] per channel (NaN to 0); the PNG writer then applies the sRGB curve. Linear
// formats (.pfm, .exr) get the renderer's radiance untouched. A clamp, not a curve: values that
// fit in [0, 1] keep their exact linear meaning, so 8-bit goldens can be compared to analytic
// radiance, and light sources simply saturate to white.
#include <filesystem>

#include "raytracer/image/image.hpp"

namespace sweeptrace {

Image to_display(const Image& linear, float exposure = 1.0f);

// True for outputs that store display values (8-bit sRGB): .png, any letter case.
bool is_display_format(const std::filesystem::path& path);

}  // namespace sweeptrace

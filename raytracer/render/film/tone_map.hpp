#pragma once
// The display transform applied before writing an 8-bit image; linear formats (.pfm, .exr) get
// the renderer's radiance untouched. Per channel, the exposed value v = radiance x 2^stops goes
// through the film's tone curve to [0, 1] (NaN to 0); the PNG writer then applies the sRGB curve.
// - clamp (the default): min(max(v, 0), 1). Values that fit in [0, 1] keep their exact linear
//   meaning, so 8-bit goldens can be compared to analytic radiance; lights saturate to white.
// - aces: Narkowicz's 2015 fit of the ACES filmic reference rendering transform,
//     f(v) = v (2.51 v + 0.03) / (v (2.43 v + 0.59) + 0.14), clamped to [0, 1]:
//   a toe that deepens shadows, a shoulder that rolls highlights off (f(1) = 0.80, and f reaches
//   1 only at v ~ 7.24), and f(0.18) = 0.27 for mid grey. It is applied per channel, so saturated
//   colours shift toward white as they brighten, as in that fit.
#include <filesystem>

#include "raytracer/image/image.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// The curve alone, on one exposed value.
float tone_curve(ToneCurve curve, float v);

Image to_display(const Image& linear, float exposure_stops = 0.0f, ToneCurve curve = ToneCurve::Clamp);

// True for outputs that store display values (8-bit sRGB): .png, any letter case.
bool is_display_format(const std::filesystem::path& path);

}  // namespace sweeptrace

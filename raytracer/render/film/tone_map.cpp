#include "raytracer/render/film/tone_map.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

namespace sweeptrace {

float tone_curve(ToneCurve curve, float v) {
    if (!(v > 0.0f)) return 0.0f;  // NaN compares false: 0
    if (curve == ToneCurve::Aces) v = v * (2.51f * v + 0.03f) / (v * (2.43f * v + 0.59f) + 0.14f);
    // The ACES fit passes 1 at v ~ 7.24 (its limit is 2.51 / 2.43); +inf gives inf / inf = NaN
    // there, which this comparison also sends to 1.
    return v < 1.0f ? v : 1.0f;
}

Image to_display(const Image& linear, float exposure_stops, ToneCurve curve) {
    const float scale = std::exp2(exposure_stops);
    Image out = linear;
    for (glm::vec3& p : out.pixels)
        for (int c = 0; c < 3; ++c) p[c] = tone_curve(curve, p[c] * scale);
    return out;
}

bool is_display_format(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".png";
}

}  // namespace sweeptrace

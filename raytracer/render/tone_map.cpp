#include "raytracer/render/tone_map.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace sweeptrace {

Image to_display(const Image& linear, float exposure) {
    Image out = linear;
    for (glm::vec3& p : out.pixels)
        for (int c = 0; c < 3; ++c) {
            const float v = p[c] * exposure;
            p[c] = v > 0.0f ? std::min(v, 1.0f) : 0.0f;  // NaN compares false: 0
        }
    return out;
}

bool is_display_format(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".png";
}

}  // namespace sweeptrace

// Stand-in textures and the scene that shows where they are seen (stand_in_mask.hpp).
#include "raytracer/scene/stand_in_mask.hpp"

#include <algorithm>
#include <system_error>

namespace sweeptrace {
namespace {

std::filesystem::path canonical_or_same(const std::filesystem::path& p) {
    std::error_code ec;
    const std::filesystem::path c = std::filesystem::weakly_canonical(p, ec);
    return ec ? p : c;
}

bool flat_and_tiny(const Image& image) {
    if (image.width > 8 || image.height > 8 || image.pixels.empty()) return false;
    return std::all_of(image.pixels.begin(), image.pixels.end(),
                       [&](const glm::vec3& p) { return p == image.pixels.front(); });
}

bool reads_any(const Material& m, const std::vector<int>& stand_ins) {
    for (const int t : {m.albedo_texture, m.roughness_texture, m.emission_texture, m.normal_texture, m.bump_texture})
        if (t >= 0 && std::find(stand_ins.begin(), stand_ins.end(), t) != stand_ins.end()) return true;
    return false;
}

}  // namespace

std::vector<int> stand_in_textures(const Scene& scene, const std::vector<std::filesystem::path>& named, bool detect_flat) {
    std::vector<std::filesystem::path> wanted;
    for (const auto& p : named) wanted.push_back(canonical_or_same(p));
    std::vector<int> out;
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const Texture& t = scene.textures[i];
        if (t.kind != Texture::Kind::Image || !t.image) continue;
        const bool is_named = std::find(wanted.begin(), wanted.end(), canonical_or_same(t.image_file)) != wanted.end();
        if (is_named || (detect_flat && flat_and_tiny(*t.image))) out.push_back(static_cast<int>(i));
    }
    return out;
}

Scene stand_in_mask_scene(const Scene& scene, const std::vector<int>& stand_ins, bool& found) {
    Scene mask = scene;
    found = false;
    mask.lights.clear();
    mask.background = Background{};  // constant black
    mask.film.guiding = false;
    mask.film.clamp_indirect = 0.0f;
    mask.film.clamp_sample = 0.0f;
    for (Material& m : mask.materials) {
        const bool stand_in = reads_any(m, stand_ins);
        found = found || stand_in;
        m.emission = glm::vec3(stand_in ? 1.0f : 0.0f);
        m.emission_texture = -1;
        m.two_sided_emission = stand_in;
        if (stand_in || m.type == Material::Type::Diffuse || m.type == Material::Type::CoatedDiffuse) {
            // Black: a stand-in is seen by its own emission only, and nothing diffuse relays it.
            if (stand_in) m.type = Material::Type::Diffuse;
            m.albedo = glm::vec3(0.0f);
            m.albedo_texture = -1;
        }
    }
    return mask;
}

}  // namespace sweeptrace

#pragma once
// Texture keys (a parameter given as an object instead of its plain value), validated and loaded;
// and the check that every textured object's shape has uv coordinates. Internal to the scene
// loader.
#include <optional>
#include <vector>

#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/load_image_file.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// Which material parameter a texture feeds: its value range, and how an 8-bit/16-bit .png (or a
// .jpg or .tga, sRGB-coded too: is_8bit_srgb in image/image.hpp) is read. Colour maps (albedo,
// emission) are sRGB-decoded to linear; data maps (roughness, normal maps) keep the file's
// stored numbers (code / 255 or / 65535). .exr, .hdr and .pfm are linear for both.
enum class TextureUse {
    Albedo,     // colours in [0, 1]
    Emission,   // radiance, each component >= 0 (a .png's values are at most 1)
    Roughness,  // data in [0, 1]; a checker's a and b are numbers
    NormalMap,  // data in [0, 1], a tangent-space normal as 0.5 + n / 2 (render/materials/shading_frame.hpp)
    BumpMap,    // data in [0, 1], a height (render/materials/shading_frame.hpp); an image, not a checker
};

// `node` is {"checker": {"a": .., "b": .., "scale": n, "uv_scale", "uv_offset"}} or {"image": {"file": ..,
// "wrap": .., "uv_scale", "uv_offset", "multiply", "invert", "encoding"}} (scenes/README.md, "Textures");
// image files are relative to the scene file's folder. An image file that one of `loaded`
// already holds is shared, not read again (a .png read both as colour and as data is read from
// disk once and converted).
Texture read_texture(const scene_json::Node& node, TextureUse use, const std::vector<Texture>& loaded);

// An image texture (wrap "repeat") from a file another file names (an .mtl's map_Kd): `relative` as
// written there, `path` where it is; shared with `loaded` as read_texture does; failures go to `fail`.
// `linear`, when set, says how an 8-bit image is read whatever the use: its stored codes (true)
// or sRGB-decoded (false) (an image texture's "encoding").
Texture image_texture(const std::string& relative, const std::filesystem::path& path, TextureUse use,
                      const std::vector<Texture>& loaded, const ImageFail& fail, std::optional<bool> linear = std::nullopt);

// read_texture appended to `textures`; returns its index.
int add_texture(const scene_json::Node& node, TextureUse use, std::vector<Texture>& textures);

// The mean over the texture's pattern (checker: (a + b) / 2; image: over its texels), the value a
// material's plain parameter keeps where one number must stand for the whole surface (an
// emission texture's light selection weight).
glm::vec3 texture_mean(const Texture& t);

// Fails at objects[i].material when an object's material reads a texture but its shape's home
// defines no uv (geometry/shapes/, `uv`).
void check_texture_uv(const Scene& scene, const scene_json::Node& objects);

}  // namespace sweeptrace

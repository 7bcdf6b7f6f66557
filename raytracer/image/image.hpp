#pragma once
// A linear-RGB float image, and reading/writing it by file extension.
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace sweeptrace {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels;  // row-major, top row first, linear radiance

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, glm::vec3(0.0f)) {}
    glm::vec3& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const glm::vec3& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// .png: 8-bit sRGB (clamped, tone mapping is the caller's); .pfm and .exr: linear float.
// Written to a temporary file beside `path` and renamed, so a failed write never leaves a partial
// file or destroys an existing one. Throws InputError (unknown extension, unwritable path).
void write_image(const Image& image, const std::filesystem::path& path);

// Reads .png, .jpg/.jpeg and .tga (sRGB decoded to linear), .pfm, .exr, .hdr (Radiance RGBE).
// Throws InputError naming the file.
Image read_image(const std::filesystem::path& path);

// A file's extension in lower case, with its dot (".png" for a.PNG, "" for none): what the
// readers and writers choose a format by.
std::string lowercase_extension(const std::filesystem::path& path);

// Whether read_image decodes `path` from sRGB-encoded codes, by its extension (case-insensitive):
// .png (8- or 16-bit), .jpg, .jpeg, .tga. Their values are display values in [0, 1]: a texture
// read as data re-encodes them (scene/load_texture.cpp), an environment refuses them.
bool is_8bit_srgb(const std::filesystem::path& path);

}  // namespace sweeptrace

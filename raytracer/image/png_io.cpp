// PNG through stb: 8-bit sRGB on write, 8- or 16-bit (any channel count) on read.
// The only file that compiles stb's implementations.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <array>
#include <climits>
#include <memory>
#include <string>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {
namespace {

void append_to_vector(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

}  // namespace

void write_png(const Image& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0 || image.width > INT_MAX / 3)
        throw InputError("cannot write '" + path.string() + "': image is " + std::to_string(image.width) + "x" +
                         std::to_string(image.height));
    std::vector<unsigned char> rgb(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = to_byte(srgb_encode(image.pixels[i][c]));
    std::vector<unsigned char> encoded;
    if (!stbi_write_png_to_func(append_to_vector, &encoded, image.width, image.height, 3, rgb.data(),
                                image.width * 3))
        throw InputError("cannot write '" + path.string() + "': PNG encoding failed");
    write_bytes(path, encoded.data(), encoded.size());
}

Image read_png(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_bytes(path);
    if (bytes.size() > static_cast<std::size_t>(INT_MAX))
        throw InputError("cannot read '" + path.string() + "': file too large");
    const auto* data = bytes.data();
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(data, size, &w, &h, &channels))
        throw InputError("cannot read '" + path.string() + "': not a valid PNG (" +
                         reason_or(stbi_failure_reason(), "unreadable header") + ")");
    check_image_size(path, "PNG", w, h);
    const bool sixteen = stbi_is_16_bit_from_memory(data, size) != 0;
    Image image;
    if (sixteen) {
        std::unique_ptr<stbi_us, StbFree> px(stbi_load_16_from_memory(data, size, &w, &h, &channels, 3));
        if (!px) throw InputError("cannot read '" + path.string() + "': not a valid PNG (" + reason_or(stbi_failure_reason(), "decoding failed") + ")");
        image = Image(w, h);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) image.pixels[i][c] = srgb_decode(px.get()[3 * i + c] / 65535.0f);
    } else {
        std::unique_ptr<stbi_uc, StbFree> px(stbi_load_from_memory(data, size, &w, &h, &channels, 3));
        if (!px) throw InputError("cannot read '" + path.string() + "': not a valid PNG (" + reason_or(stbi_failure_reason(), "decoding failed") + ")");
        std::array<float, 256> table;
        for (int v = 0; v < 256; ++v) table[v] = srgb_decode(v / 255.0f);
        image = Image(w, h);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) image.pixels[i][c] = table[px.get()[3 * i + c]];
    }
    return image;
}

}  // namespace sweeptrace::formats

// Radiance .hdr (RGBE) through stb_image's float loader (compiled in png_io.cpp): linear
// radiance, read only (the renderer writes .pfm and .exr for linear output).
#include <stb/stb_image.h>

#include <climits>
#include <memory>
#include <string>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {

Image read_hdr(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = read_bytes(path);
    if (bytes.size() > static_cast<std::size_t>(INT_MAX))
        throw InputError("cannot read '" + path.string() + "': file too large");
    const int size = static_cast<int>(bytes.size());
    if (!stbi_is_hdr_from_memory(bytes.data(), size))
        throw InputError("cannot read '" + path.string() + "': not a Radiance HDR file");
    int w = 0, h = 0, channels = 0;
    struct Free {
        void operator()(float* p) const { stbi_image_free(p); }
    };
    std::unique_ptr<float, Free> px(stbi_loadf_from_memory(bytes.data(), size, &w, &h, &channels, 3));
    if (!px) throw InputError("cannot read '" + path.string() + "': not a valid HDR file (" + stbi_failure_reason() + ")");
    Image image(w, h);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i][c] = px.get()[3 * i + c];
    return image;
}

}  // namespace sweeptrace::formats

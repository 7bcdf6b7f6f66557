#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <memory>
#include <string>

#include "raytracer/image/alpha.hpp"
#include "raytracer/image/atomic_file.hpp"
#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

AlphaChannel png_alpha(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = formats::read_bytes(path);
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw InputError("cannot read '" + path.string() + "': file too large");
    const int size = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &channels))
        throw InputError("cannot read '" + path.string() + "': not a valid PNG (" + stbi_failure_reason() + ")");
    AlphaChannel a;
    if (channels != 2 && channels != 4) return a;
    std::unique_ptr<stbi_us, void (*)(void*)> px(stbi_load_16_from_memory(bytes.data(), size, &w, &h, &channels, 4),
                                                stbi_image_free);
    if (!px) throw InputError("cannot read '" + path.string() + "': not a valid PNG (" + stbi_failure_reason() + ")");
    a.values.resize(static_cast<std::size_t>(w) * h);
    for (std::size_t i = 0; i < a.values.size(); ++i) a.values[i] = px.get()[4 * i + 3] / 65535.0f;
    return a;
}

AlphaChannel exr_alpha(const std::filesystem::path& path) {
    AlphaChannel a;
    a.premultiplied = true;
    try {
        Imf::InputFile file(path.c_str());
        if (!file.header().channels().findChannel("A")) return a;
        const Imath::Box2i window = file.header().dataWindow();
        const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
        a.values.resize(static_cast<std::size_t>(w * h));
        char* base = reinterpret_cast<char*>(a.values.data()) -
                     (static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * w) *
                         static_cast<std::ptrdiff_t>(sizeof(float));
        Imf::FrameBuffer frame;
        frame.insert("A", Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * static_cast<std::size_t>(w)));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
    } catch (const std::exception& e) {
        throw InputError("cannot read '" + path.string() + "': not a valid EXR file (" + e.what() + ")");
    }
    return a;
}

}  // namespace

AlphaChannel read_alpha(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".png") return png_alpha(path);
    if (ext == ".exr") return exr_alpha(path);
    return {};
}

Image composite_over(const Image& image, const AlphaChannel& alpha, const glm::vec3& background) {
    if (!alpha.present()) return image;
    Image out = image;
    for (std::size_t i = 0; i < out.pixels.size() && i < alpha.values.size(); ++i) {
        const float a = alpha.values[i];
        out.pixels[i] = (alpha.premultiplied ? image.pixels[i] : image.pixels[i] * a) + background * (1.0f - a);
    }
    return out;
}

void write_exr_with_alpha(const Image& image, const std::vector<float>& alpha, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0 || alpha.size() != image.pixels.size())
        throw InputError("cannot write '" + path.string() + "': alpha has " + std::to_string(alpha.size()) +
                         " values for " + std::to_string(image.pixels.size()) + " pixels");
    write_atomically(path, [&](const std::filesystem::path& temp) {
        try {
            Imf::Header header(image.width, image.height);
            Imf::FrameBuffer frame;
            const std::size_t xstride = sizeof(glm::vec3), ystride = xstride * image.width;
            auto* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
            const char* names[3] = {"R", "G", "B"};
            for (int c = 0; c < 3; ++c) {
                header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
                frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xstride, ystride));
            }
            header.channels().insert("A", Imf::Channel(Imf::FLOAT));
            frame.insert("A", Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(alpha.data())),
                                         sizeof(float), sizeof(float) * image.width));
            Imf::OutputFile file(temp.c_str(), header);
            file.setFrameBuffer(frame);
            file.writePixels(image.height);
        } catch (const std::exception& e) {
            throw InputError("cannot write '" + path.string() + "': " + e.what());
        }
    });
}

}  // namespace sweeptrace

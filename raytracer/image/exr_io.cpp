// OpenEXR: written as 32-bit float R, G, B (linear, ZIP-compressed); read from any pixel type
// (half, float, uint) of R, G, B, or of Y alone for a grey image.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {

// exr_header_window (image_formats.hpp): the data window as the first header states it, read before OpenEXR sees the file:
// Imf::InputFile allocates line buffers from the header's width while it opens the file, so a
// 391-byte file claiming 3-million-pixel lines took 1.8 s and hundreds of MB under ASan before
// any check could run (found by tests/fuzz/fuzz_exr). Attributes are name\0 type\0 int32 size,
// then the value; an empty name ends the header. Nullopt when the bytes are not that shape
// (OpenEXR then says what is wrong).
std::optional<std::pair<long long, long long>> exr_header_window(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> b(1 << 16);
    in.read(b.data(), static_cast<std::streamsize>(b.size()));
    b.resize(static_cast<std::size_t>(in.gcount()));
    if (b.size() < 8 || std::memcmp(b.data(), "\x76\x2f\x31\x01", 4) != 0) return std::nullopt;
    auto text = [&](std::size_t& at) -> std::optional<std::string> {
        const auto end = std::find(b.begin() + static_cast<std::ptrdiff_t>(at), b.end(), '\0');
        if (end == b.end()) return std::nullopt;
        std::string t(b.begin() + static_cast<std::ptrdiff_t>(at), end);
        at = static_cast<std::size_t>(end - b.begin()) + 1;
        return t;
    };
    auto int32 = [&](std::size_t at) {
        std::int32_t v;
        std::memcpy(&v, b.data() + at, 4);
        return static_cast<long long>(v);
    };
    for (std::size_t at = 8;;) {
        const auto name = text(at);
        if (!name || name->empty()) return std::nullopt;
        const auto type = text(at);
        if (!type || b.size() - at < 4) return std::nullopt;
        const long long size = int32(at);
        at += 4;
        if (size < 0 || static_cast<unsigned long long>(size) > b.size() - at) return std::nullopt;
        if (*name == "dataWindow" && *type == "box2i" && size == 16)
            return std::pair{int32(at + 8) - int32(at) + 1, int32(at + 12) - int32(at + 4) + 1};
        at += static_cast<std::size_t>(size);
    }
}

void write_exr(const Image& image, const std::filesystem::path& path) {
    if (image.width <= 0 || image.height <= 0)
        throw InputError("cannot write '" + path.string() + "': image is " + std::to_string(image.width) + "x" +
                         std::to_string(image.height));
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        const char* names[3] = {"R", "G", "B"};
        Imf::FrameBuffer frame;
        const std::size_t xstride = sizeof(glm::vec3), ystride = xstride * image.width;
        auto* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
        for (int c = 0; c < 3; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xstride, ystride));
        }
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
    } catch (const std::exception& e) {
        throw InputError("cannot write '" + path.string() + "': " + reason_or(e.what(), "OpenEXR failed"));
    }
}

Image read_exr(const std::filesystem::path& path) {
    check_image_file(path);
    if (const auto window = exr_header_window(path)) check_image_size(path, "EXR data window", window->first, window->second);
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
        reserve_image(path, "EXR data window", w, h);
        const Imf::ChannelList& channels = file.header().channels();
        const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
        const bool grey = !rgb && channels.findChannel("Y");
        if (!rgb && !grey)
            throw InputError("cannot read '" + path.string() + "': EXR has neither R, G, B nor Y channels");
        Image image(static_cast<int>(w), static_cast<int>(h));
        const std::size_t xstride = sizeof(glm::vec3), ystride = xstride * image.width;
        // The slice's base is the address of pixel (0, 0) of the data window's coordinate system.
        char* base = reinterpret_cast<char*>(image.pixels.data()) -
                     static_cast<std::ptrdiff_t>(window.min.x) * static_cast<std::ptrdiff_t>(xstride) -
                     static_cast<std::ptrdiff_t>(window.min.y) * static_cast<std::ptrdiff_t>(ystride);
        // A grey image's Y goes into the red slot and is copied to green and blue afterwards.
        Imf::FrameBuffer frame;
        const char* names[3] = {"R", "G", "B"};
        for (int c = 0; c < (rgb ? 3 : 1); ++c)
            frame.insert(rgb ? names[c] : "Y", Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xstride, ystride));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        if (grey)
            for (auto& p : image.pixels) p = glm::vec3(p.x);
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError("cannot read '" + path.string() + "': not a valid EXR file (" + reason_or(e.what(), "OpenEXR failed") + ")");
    }
}

}  // namespace sweeptrace::formats

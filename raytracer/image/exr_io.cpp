// OpenEXR: written as 32-bit float R, G, B (linear, ZIP-compressed); read from any pixel type
// (half, float, uint) of R, G, B, or of Y alone for a grey image.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <string>

#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace::formats {

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
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
        check_image_size(path, "EXR data window", w, h);
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

// Named float channels of an EXR (exr_channels.hpp): the denoiser's multi-layer feature images.
// Bounded as read_exr is: the header's size checked from the bytes before OpenEXR opens the file,
// and the channels charged to the load budget before they are allocated.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <cstdint>
#include <string>

#include "raytracer/image/atomic_file.hpp"
#include "raytracer/image/exr_channels.hpp"
#include "raytracer/image/image_formats.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"

namespace sweeptrace {
namespace {

std::string window_text(const Imath::Box2i& w) {
    return std::to_string(static_cast<long long>(w.max.x) - w.min.x + 1) + "x" +
           std::to_string(static_cast<long long>(w.max.y) - w.min.y + 1);
}

}  // namespace

ExrChannels read_exr_channels(const std::filesystem::path& path) {
    formats::check_image_file(path);
    if (const auto window = formats::exr_header_window(path))
        formats::check_image_size(path, "EXR data window", window->first, window->second);
    const std::string where = "cannot read '" + path.string() + "': ";
    try {
        {
            Imf::MultiPartInputFile parts(path.c_str());
            if (parts.parts() > 1) {
                std::string sizes;
                for (int p = 0; p < parts.parts(); ++p)
                    sizes += (p ? ", " : "") + window_text(parts.header(p).dataWindow());
                throw InputError(where + "EXR has " + std::to_string(parts.parts()) +
                                 " parts (layers of sizes " + sizes + "); a single-part EXR with every layer the image's size is needed");
            }
        }
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
        formats::check_image_size(path, "EXR data window", w, h);
        const Imf::ChannelList& list = file.header().channels();
        std::uint64_t count = 0;
        for (auto c = list.begin(); c != list.end(); ++c) {
            if (c.channel().xSampling != 1 || c.channel().ySampling != 1)
                throw InputError(where + "channel '" + c.name() + "' is subsampled " + std::to_string(c.channel().xSampling) + "x" +
                                 std::to_string(c.channel().ySampling) + ": its layer is smaller than the image's " + window_text(window));
            ++count;
        }
        charge_load_memory(count * static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) * sizeof(float), path.string(),
                           std::to_string(count) + " EXR channels of " + window_text(window));
        ExrChannels image;
        image.width = static_cast<int>(w);
        image.height = static_cast<int>(h);
        Imf::FrameBuffer frame;
        const std::size_t xstride = sizeof(float), ystride = xstride * static_cast<std::size_t>(w);
        for (auto c = list.begin(); c != list.end(); ++c) {
            std::vector<float>& values = image.channels[c.name()];
            values.assign(static_cast<std::size_t>(w * h), 0.0f);
            // The slice's base is the address of pixel (0, 0) of the data window's coordinates.
            char* base = reinterpret_cast<char*>(values.data()) -
                         static_cast<std::ptrdiff_t>(window.min.x) * static_cast<std::ptrdiff_t>(xstride) -
                         static_cast<std::ptrdiff_t>(window.min.y) * static_cast<std::ptrdiff_t>(ystride);
            frame.insert(c.name(), Imf::Slice(Imf::FLOAT, base, xstride, ystride));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        if (const auto* spp = file.header().findTypedAttribute<Imf::IntAttribute>(kExrSppAttribute)) image.spp = spp->value();
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(where + "not a valid EXR file (" + reason_or(e.what(), "OpenEXR failed") + ")");
    }
}

void write_exr_channels(const ExrChannels& image, const std::filesystem::path& path) {
    const std::size_t n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    if (image.width <= 0 || image.height <= 0 || image.channels.empty())
        throw InputError("cannot write '" + path.string() + "': image is " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " with " + std::to_string(image.channels.size()) + " channels");
    for (const auto& [name, values] : image.channels)
        if (values.size() != n)
            throw InputError("cannot write '" + path.string() + "': channel '" + name + "' has " + std::to_string(values.size()) +
                             " values, not " + std::to_string(n));
    write_atomically(path, [&](const std::filesystem::path& temp) {
        try {
            Imf::Header header(image.width, image.height);
            header.compression() = Imf::ZIP_COMPRESSION;
            if (image.spp != -1) header.insert(kExrSppAttribute, Imf::IntAttribute(image.spp));
            Imf::FrameBuffer frame;
            const std::size_t xstride = sizeof(float), ystride = xstride * static_cast<std::size_t>(image.width);
            for (const auto& [name, values] : image.channels) {
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
                frame.insert(name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(values.data())), xstride, ystride));
            }
            Imf::OutputFile file(temp.c_str(), header);
            file.setFrameBuffer(frame);
            file.writePixels(image.height);
        } catch (const InputError&) {
            throw;
        } catch (const std::exception& e) {
            throw InputError("cannot write '" + path.string() + "': " + reason_or(e.what(), "OpenEXR failed"));
        }
    });
}

}  // namespace sweeptrace

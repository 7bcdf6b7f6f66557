#pragma once
// An OpenEXR file as named float channels: what a multi-layer EXR holds ("R", "Albedo.R",
// "Even.Ns.X", ...), for the denoiser's feature images (denoise/feature_image.hpp), which
// image.hpp's RGB Image cannot carry. Every channel is read as 32-bit float (OpenEXR converts
// half and uint), row-major, top row first.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sweeptrace {

struct ChannelImage {
    int width = 0, height = 0;
    std::map<std::string, std::vector<float>> channels;  // each width * height values
    std::map<std::string, int> int_attributes;           // the header's int attributes, by name

    // The channel's values, or nullptr when the file has no channel of that name.
    const std::vector<float>* find(const std::string& name) const {
        const auto it = channels.find(name);
        return it == channels.end() ? nullptr : &it->second;
    }
};

// Reads every channel of a single-part EXR. Throws InputError naming the file when it is not an
// EXR, its size is out of the readers' range (image_formats.hpp), it has several parts (the
// layers of a multi-part file may differ in size: named with their sizes) or a channel is
// subsampled (its layer is smaller than the image: named).
ChannelImage read_exr_channels(const std::filesystem::path& path);

// Writes every channel as 32-bit float, ZIP-compressed, atomically (atomic_file.hpp), with the
// int attributes. Throws InputError naming the file when a channel's size is not width * height
// or the write fails.
void write_exr_channels(const ChannelImage& image, const std::filesystem::path& path);

}  // namespace sweeptrace

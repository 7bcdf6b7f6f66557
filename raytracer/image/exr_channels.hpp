#pragma once
// An OpenEXR file as named float channels: what a multi-layer EXR holds ("R", "Albedo.R",
// "Even.Ns.X", ...): the feature image of `render --aovs` (feature_exr.hpp) as the denoiser and
// the tests read it, which image.hpp's RGB Image cannot carry. Every channel is read as 32-bit
// float (OpenEXR converts half and uint), row-major, top row first.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sweeptrace {

// The int header attribute that holds a render's samples per pixel.
inline constexpr const char* kExrSppAttribute = "sweeptrace:spp";

struct ExrChannels {
    int width = 0, height = 0;
    int spp = -1;  // kExrSppAttribute, -1 when absent
    std::map<std::string, std::vector<float>> channels;  // each width * height values

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
ExrChannels read_exr_channels(const std::filesystem::path& path);

// Writes every channel as 32-bit float, ZIP-compressed, atomically (atomic_file.hpp), with spp
// when it is not -1. Throws InputError naming the file when a channel's size is not width * height
// or the write fails.
void write_exr_channels(const ExrChannels& image, const std::filesystem::path& path);

}  // namespace sweeptrace

#pragma once
// The feature image (`render --aovs -o out.exr`): one OpenEXR file of FLOAT channels, all the
// render's size, named as pbrt-v4's `gbuffer` film names the quantities it has, so other tools
// read them:
//   R, G, B                       the colour, the mean of all samples (what `render -o` writes)
//   Variance.R/G/B                the variance of that mean (what `render --variance` writes:
//                                 sample variance / count; pbrt's Variance is of the samples)
//   Albedo.R/G/B, Ns.X/Y/Z, P.X/P.Y/P.Z   the features (image/feature_sums.hpp)
//   AlbedoVariance.R/G/B, NsVariance.X/Y/Z, PVariance.Z   the variances of their means
//   Even.R/G/B, Even.Albedo.R/G/B, Even.Ns.X/Y/Z, Even.P.X/Y/Z   the even samples' means
//   Odd.R/G/B, Odd.Albedo.R/G/B, Odd.Ns.X/Y/Z, Odd.P.X/Y/Z       the odd samples' means
// and the int attribute `sweeptrace:spp`, the render's samples per pixel (nominal under
// adaptive sampling). This is the contract `sweeptrace denoise` reads.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "raytracer/image/feature_sums.hpp"

namespace sweeptrace {

// Every channel name write_feature_exr writes, in its order.
std::vector<std::string> feature_exr_channel_names();

// Atomic (temporary file + rename). Throws InputError naming `path`.
void write_feature_exr(const FeatureLayers& layers, int spp, const std::filesystem::path& path);

// Every channel of an EXR file as float, by name (tests, tools): the data window's size, and
// `sweeptrace:spp` when present (else -1). Throws InputError naming `path`.
struct ExrChannels {
    int width = 0, height = 0;
    int spp = -1;
    std::map<std::string, std::vector<float>> channels;
};
ExrChannels read_exr_channels(const std::filesystem::path& path);

}  // namespace sweeptrace

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

#include "raytracer/image/exr_channels.hpp"
#include "raytracer/image/feature_sums.hpp"

namespace sweeptrace {

// Every channel name write_feature_exr writes, in its order.
std::vector<std::string> feature_exr_channel_names();

// The layers of `sums` (row-major, width x height; feature_layers' values), computed and written a
// block of rows at a time. Atomic (temporary file + rename). Throws InputError naming `path`.
void write_feature_exr(const std::vector<FeatureSums>& sums, int width, int height, int spp, const std::filesystem::path& path);

// It is read back, as every EXR's named channels are, by read_exr_channels (exr_channels.hpp).

}  // namespace sweeptrace

#pragma once
// The feature image that `render --aovs` writes and NFOR reads, by channel name (pbrt-v4's
// gbuffer film's names where pbrt has the quantity; docs/denoising.md is the contract):
//   R, G, B and Variance.R/G/B          colour, mean of all samples, and its variance of the mean
//   Albedo.R/G/B, Ns.X/Y/Z, P.Z          the features NFOR regresses on (albedo, shading normal,
//                                        camera-space depth at the first non-specular vertex)
//   AlbedoVariance.R/G/B, NsVariance.X/Y/Z, PVariance.Z   their variances of the mean
//   Even.<name>, Odd.<name>              the means of the even and of the odd samples, for the
//                                        colour and every feature above
#include <string>
#include <vector>

#include "raytracer/denoise/nfor.hpp"
#include "raytracer/image/exr_channels.hpp"

namespace sweeptrace::denoise {

// The colour's channels and the features', in the order NFOR holds them.
const std::vector<std::string>& color_channel_names();
const std::vector<std::string>& feature_channel_names();

// The variance channel of a colour or feature channel: "R" -> "Variance.R",
// "Albedo.R" -> "AlbedoVariance.R" (pbrt-v4's gbuffer names them so).
std::string variance_channel_name(const std::string& channel);

// Every channel name NFOR reads (colour, features, their variances and halves).
std::vector<std::string> required_channel_names();

// NFOR's input from a feature image. Throws InputError naming `file` and the first channel
// missing ("... has no channel 'Even.Albedo.R' ...") or the first value that is not finite (or a
// negative variance), with its pixel.
NforInput nfor_input(const ExrChannels& image, const std::string& file);

}  // namespace sweeptrace::denoise

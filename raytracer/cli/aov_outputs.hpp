#pragma once
// Where feature outputs (render --aovs, or merge of parts rendered with them) go, beside the
// image OUT the command writes anyway:
//   OUT.exr        one file: the feature image (image/feature_exr.hpp), whose R, G, B are the
//                  very image `-o OUT.exr` writes without --aovs, plus every feature layer
//   OUT.png, .pfm  the image as without --aovs, and beside it, as linear float PFM (exact values,
//                  no display mapping): STEM.albedo.pfm, STEM.normal.pfm and STEM.depth.pfm
//                  (P.Z in all three channels), STEM being OUT without its extension. The
//                  variances and half buffers are in the EXR form only.
// Both commands check these files by the one output rule (add_aov_outputs, output_guard.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include "raytracer/cli/output_guard.hpp"
#include "raytracer/image/feature_sums.hpp"
#include "raytracer/image/image.hpp"

namespace sweeptrace {

// The files written besides OUT itself (none for an EXR).
std::vector<std::filesystem::path> aov_side_files(const std::filesystem::path& out);

// Adds the side files to a command's outputs (output_guard.hpp), so they join its one rule:
// no input overwritten, no two outputs the same, no device or FIFO replaced.
void add_aov_outputs(std::vector<NamedFile>& outputs, const std::filesystem::path& out);

// Writes `image` (as OUT's format wants it: display-mapped for PNG) to OUT with the features of
// `sums` (image.width x image.height, row-major) as above; `spp` goes into the EXR's sweeptrace:spp.
void write_image_with_aovs(const Image& image, const std::vector<FeatureSums>& sums, int spp, const std::filesystem::path& out);

}  // namespace sweeptrace

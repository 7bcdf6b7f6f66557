#pragma once
// A farm part: the exact per-pixel sums of sample indices [sample_begin, sample_end) of one
// render, and what identifies that render, so that parts from different renders are never summed.
// Under adaptive sampling (render --adaptive, render/adaptive_sampling.hpp) the range is nominal
// spp and each pixel holds its own count of samples, which the part stores.
//
// File format (`render --samples A:B -o part.exr`): an OpenEXR file any viewer opens, whose
// R, G, B (FLOAT) hold the part's own mean (a preview), and whose twelve UINT channels
// `sum.R.0` .. `sum.B.3` hold each channel's 128-bit two's-complement fixed-point sum
// (partial_sum.hpp) as four 32-bit words, least significant first; an adaptive part also has a
// UINT channel `count`, each pixel's number of samples; a part of a render with feature outputs
// (render --aovs) also has the kFeatureWords UINT channels `aov.*` of each pixel's FeatureSums
// (image/feature_sums.hpp: the colour and features of its even and odd samples, and the exact
// sums of squares). String attributes:
//   sweeptrace.part         format version, "5" (formats 1 to 4, before adaptive parts, feature
//                           outputs, the features' narrower sums and the sampler, are refused:
//                           their parts came from an older program, which merge refuses anyway)
//   sweeptrace.sceneHash    hash of the scene file and the mesh files it loads
//   sweeptrace.seed, sweeptrace.maxDepth, sweeptrace.accel, sweeptrace.version (the program's)
//   sweeptrace.integrator   "path", "bdpt" or "vcm"
//   sweeptrace.sampler      "sobol", "sobol-halves" or "independent": which numbers a sample
//                           index draws, so parts of different samplers never merge
//   sweeptrace.adaptive     "off", "on" or "relative": render --adaptive
//   sweeptrace.aovs         "off" or "on": render --aovs (or the scene's film.aovs)
//   sweeptrace.spp          samples per pixel of the whole render the part belongs to
//   sweeptrace.samples      "A:B", the part's half-open range of sample indices
//   sweeptrace.fractionBits "56", the fixed point's scale
//   sweeptrace.checksum     FNV-1a 64 of the sums, the counts, the feature sums and the
//                           attributes above, in hex
// The resolution is the data window. A part that reads and whose checksum matches "verifies".
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "raytracer/image/feature_sums.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/partial_sum.hpp"

namespace sweeptrace {

// Everything that must be equal for two parts to be parts of the same image.
struct RenderIdentity {
    std::string scene_hash;
    int width = 0, height = 0;
    std::uint64_t seed = 0;
    int max_depth = 0;
    std::string accel;
    std::string integrator;  // film.integrator after --integrator ("path", "bdpt", "vcm")
    std::string sampler;     // film.sampler after --sampler and --aovs ("sobol", "sobol-halves", "independent")
    std::string adaptive = "off";  // render --adaptive: "off", "on" or "relative"
    std::string aovs = "off";      // feature outputs (render --aovs): "off" or "on"
    std::string version;
    int spp = 0;  // the whole render's samples per pixel: the parts cover [0, spp)

    bool operator==(const RenderIdentity&) const = default;
};

// The first field in which `a` and `b` differ, as "seed 1 vs 2"; empty when they are equal.
std::string identity_difference(const RenderIdentity& a, const RenderIdentity& b);

struct PartialImage {
    RenderIdentity id;
    int sample_begin = 0, sample_end = 0;  // [begin, end): every pixel holds end - begin samples
    std::vector<PixelSum> sums;            // row-major, id.width * id.height
    // Adaptive (id.adaptive != "off"): each pixel's own count of samples, row-major; empty for a
    // uniform part, whose pixels all hold end - begin. A pixel may hold none in a short range.
    std::vector<int> counts;
    // With feature outputs (id.aovs "on"): each pixel's exact feature sums, row-major; else empty.
    std::vector<FeatureSums> features;

    int count(std::size_t pixel) const { return counts.empty() ? sample_end - sample_begin : counts[pixel]; }
    Image mean() const;  // mean_of each sum over its pixel's count (black for none)
};

// Atomic (temporary file + rename). Throws InputError naming `path`.
void write_partial(const PartialImage& part, const std::filesystem::path& path);

// Throws InputError naming `path` when it is not a sweeptrace part, is truncated, lacks an
// attribute, or its checksum does not match its contents.
PartialImage read_partial(const std::filesystem::path& path);

// The identity and range only (`sums` empty): cheap, for checking a set of parts before reading
// their sums. Throws as read_partial does, except that the checksum is not checked.
PartialImage read_partial_header(const std::filesystem::path& path);

// Checks that `parts` (their sums are not looked at) are the whole of one render, and returns
// their indices in order of their ranges, the order to add them in. Throws InputError when there
// are no parts, two are of different renders (naming both files and the field), two ranges
// overlap (naming both files and the shared samples), or samples of [0, spp) are missing
// (naming the range). `names[i]` is the file `parts[i]` was read from.
std::vector<std::size_t> check_partials(const std::vector<PartialImage>& parts, const std::vector<std::string>& names);

// check_partials, then the sums (and an adaptive render's counts, and feature sums) added in that order: the whole
// render as one part. Throws InputError should a pixel's total count not fit in an int.
PartialImage merge_partials(const std::vector<PartialImage>& parts, const std::vector<std::string>& names);

// Adds `part` (read from `name`) to `whole` (its id set; sums empty or of the same size): the
// sums, and under adaptive sampling the counts. The merge's one step, for a merge that reads one
// part at a time. Throws InputError should a pixel's count not fit in an int.
void add_part(PartialImage& whole, const PartialImage& part, const std::string& name);

}  // namespace sweeptrace

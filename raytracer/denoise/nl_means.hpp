#pragma once
// NL-means with the variance-aware patch distance of Rousselle, Manzi and Zwicker, "Robust
// denoising using feature and color information" (2013), as NFOR uses it (Bitterli et al. 2016,
// sections 5.1 and 5.3): for pixels p, q of a guide u with variance of the mean Var,
//     d(p, q) = ((u(p) - u(q))^2 - (Var p + min(Var p, Var q))) / (k^2 (Var p + Var q)),
// averaged over the (2F + 1)^2 patch pairs around p and q (clipped to the image), and the weight
// of q in p's average is exp(-max(0, d)). Subtracting the variance makes two noisy copies of the
// same value distance 0 in expectation; k scales how far apart they may be. Each channel is
// weighted by its own distance (nl_means), or all by the largest (regression.hpp).
#include <vector>

#include "raytracer/denoise/filter_isa.hpp"
#include "raytracer/denoise/planes.hpp"

namespace sweeptrace::denoise {

struct NlMeansParams {
    int patch_radius = 3;   // F: patches of (2F + 1)^2 pixels
    int search_radius = 5;  // R: a pixel averages its (2R + 1)^2 neighbours
    float k = 0.5f;         // larger: dissimilar patches count more (stronger filtering)
    // The guide's variance is this times `variance`: 2 when a half buffer (half the samples) is
    // guided by the full image's variance of the mean.
    float variance_scale = 1.0f;
};

// Working buffers of largest_patch_distances, reused across offsets by one task.
struct PatchScratch {
    std::vector<float> pixel, row, column, count, largest;
};

// The largest over the channels of `guide` of the patch distance d, for every pixel p of `tile`
// whose neighbour p + (dx, dy) is inside the image: written to out[(y - tile.y0) * row_stride +
// (x - tile.x0)]. Returns the part of `tile` that was written (pixels whose neighbour is outside
// are left as they were). The channels' patch sums are compared before the division by the
// patch's pixel count, the same for every channel: division by a positive number keeps the
// order, so this is the largest of the channels' distances, to the bit.
Rect largest_patch_distances(const Planes& guide, const Planes& variance, const NlMeansParams& params, const Rect& tile, int dx, int dy,
                             PatchScratch& scratch, float* out, std::size_t row_stride, FilterIsa isa);

// `image` filtered by NL-means weights computed on `guide` (same size; `variance` is the guide's
// variance of the mean): each channel averaged with its own weights, those of guide channel c mod
// (guide channels). The image's channels are a multiple of the guide's: several images that
// share a guide (NFOR's two error maps) are filtered at the cost of one set of weights. Parallel
// over tiles, each pixel's sum taken in one fixed order: bit-identical at any thread count.
Planes nl_means(const Planes& image, const Planes& guide, const Planes& variance, const NlMeansParams& params, FilterIsa isa);

}  // namespace sweeptrace::denoise

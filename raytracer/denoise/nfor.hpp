#pragma once
// NFOR, "Nonlinearly Weighted First-order Regression for Denoising Monte Carlo Renderings"
// (Bitterli, Rousselle, Moon, Iglesias-Guitian, Adler, Mitchell, Jarosz, Novak 2016), written
// from the paper with Tungsten's public implementation (src/denoiser/) as the reading of its
// parameters. The steps, each half buffer filtered with what the other half gives, so a filter's
// weights and features never share the noise of the colour they average:
//   1. feature prefiltering (5.1): each half's features by NL-means guided by the other half's;
//   2. regression (5.2): each half's colour by collaborative_regression on the other half's
//      prefiltered features, weighted on the other half's colour, for two candidate bandwidths k;
//   3. selection (5.3): per pixel and channel, the candidate of smaller estimated error (from the
//      two halves' disagreement, the error map smoothed by NL-means), the binary map smoothed the
//      same way and used to blend the candidates;
//   4. second pass (5.4): the two filtered halves' mean regressed once more on the halves' mean
//      features, with the halves' difference as its variance.
#include <cstdint>

#include "raytracer/denoise/filter_isa.hpp"
#include "raytracer/denoise/planes.hpp"

namespace sweeptrace::denoise {

// What NFOR reads: colour (3 channels) and features (any channels), each as the mean of all
// samples, the means of the even and the odd samples, and the variance of the mean.
struct Buffers {
    Planes mean, even, odd, variance;
};

struct NforInput {
    Buffers color;
    Buffers features;
};

// The denoised colour (3 channels, the input's size), its loops run with `isa`. Parallel over
// tiles in the caller's tbb::task_arena; bit-identical at any thread count and either ISA.
Planes nfor(const NforInput& input, FilterIsa isa);

// An upper bound of what nfor allocates beyond its input for a width x height image with
// `feature_channels` features and `threads` worker threads, in bytes: for refusing an image
// before the work starts (sweeptrace denoise charges it to the memory budget).
std::uint64_t nfor_memory_bytes(int width, int height, int feature_channels, int threads);

}  // namespace sweeptrace::denoise

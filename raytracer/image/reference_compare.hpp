#pragma once
// A render judged against a reference image of higher resolution rendered by another program
// (`sweeptrace reference-check`, docs/reference-scenes.md): the reference brought to the render's
// size, the noise of both, and 8x8 block statistics of the difference.
//
// Downsampling is a box filter over whole source pixels: each output pixel is the plain mean of
// its `factor` x `factor` source pixels (no resampling across pixel edges, so the factor must
// divide both sides). The render should then use a box pixel filter too: its pixel is the image
// integrated over the same footprint.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "raytracer/image/image.hpp"

namespace sweeptrace {

struct DownsampledReference {
    Image image;                      // mean of the pixel's finite source pixels
    std::vector<std::uint8_t> valid;  // 0 where any of its source pixels is non-finite (masked)
    // The reference's own noise, as the variance of each output pixel's mean. Per source pixel the
    // noise variance is estimated from its residual against the mean of its 3x3 neighbourhood
    // (k finite pixels, itself included): for independent noise of variance s^2 on a locally flat
    // image, E[r^2] = s^2 (k - 1) / k, so s^2 ~ r^2 k / (k - 1). The pixel's variance is the mean of
    // those over its source pixels, divided by their count. Where the image is not flat (edges,
    // texture) the residual holds detail too, so the estimate is too large there: the test gets
    // more lenient, never stricter. Single estimates are noisy; block statistics pool them.
    Image variance;
};

// `factor` >= 1 must divide reference.width and reference.height (the caller checks: InputError).
DownsampledReference downsample_reference(const Image& reference, int factor);

// Per block of `block` x `block` output pixels (the last row and column may be smaller), with
// every sum taken over the pixels that are valid in `valid` (the reference's, and-ed with any
// mask), and a block tested when at least half of a full block's pixels are valid:
//   z_c = (mean_c(ours) - mean_c(ref)) / sqrt(sum (Var_ours + Var_ref)) * n   per channel c,
// the difference of two independent means over the sum of their variances.
struct BlockComparison {
    int blocks_x = 0, blocks_y = 0, block = 8;
    std::vector<double> z;               // per block (row-major): the signed z_c of largest |z_c|; NaN if not tested
    std::vector<double> relative_error;  // per block: (sum_c ours - sum_c ref) / sum_c ref, NaN if not tested or ref is 0
    std::size_t tested = 0;              // blocks tested
    double share_within_3 = 0.0;         // of tested blocks: every channel |z| < 3
    double share_within_5 = 0.0;         // every channel |z| < 5
    double median_relative_error = 0.0;  // median over tested blocks with a non-zero reference
    glm::dvec3 mean_ratio{0.0};          // per channel: sum over valid pixels of ours / of ref
    double valid_share = 0.0;            // valid pixels / all pixels
};

// All images the same size; `valid` one byte per pixel. `our_variance_scale` multiplies the sum
// of our pixels' variances in every block (block_variance_scale below; 1 for independent pixels).
BlockComparison compare_blocks(const Image& ours, const Image& our_variance, const Image& reference,
                               const Image& reference_variance, const std::vector<std::uint8_t>& valid,
                               int block = 8, double our_variance_scale = 1.0);

// The variance of a block mean over what the sum of its pixels' variances says, measured on
// independent replicas. Summing pixel variances assumes independent pixels; a bidirectional
// render's light-tracing splats land on many pixels of one sample pass, which correlates
// neighbouring pixels: positively where one light subpath's vertices land near each other,
// negatively where one vertex's splat lands on one pixel of a block or another, never both. `batches` are K >= 2 independent renders of the same image (disjoint sample ranges of
// one render, equal sample counts), `whole_variance` the per-pixel variance of their mean (what
// `render --variance` gives for the whole render). Per block and channel, the replicas' variance of
// the whole mean is the sample variance of the K batch block means / K; the result is the sum of
// those over every tested block and channel divided by the sum of the pixel-variance sums: pooled,
// so it is a stable figure (each block's own replica variance has only K - 1 degrees of freedom,
// whose heavy-tailed z would fail more than the 3-sigma share allows). 1 when nothing is tested.
double block_variance_scale(const std::vector<Image>& batches, const Image& whole_variance,
                            const std::vector<std::uint8_t>& valid, int block = 8);

// The picture for people: ours | reference | z map, side by side, linear RGB for write_image's
// 8-bit sRGB PNG. Both renders share one scale, 1 / (the 99th percentile of the reference's
// largest channel over valid pixels), clamped at 1. The z map is per block: black at z = 0, red
// where ours is brighter, blue where darker, full at |z| >= 5; dark grey for blocks not tested,
// mid grey on the pixels that are masked.
Image comparison_picture(const Image& ours, const Image& reference, const std::vector<std::uint8_t>& valid,
                         const BlockComparison& blocks);

}  // namespace sweeptrace

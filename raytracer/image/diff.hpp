#pragma once
// Comparing two images: plain metrics for `sweeptrace diff`, a false-colour heatmap, and a
// noise-aware block test for comparing a Monte Carlo render against a golden image.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "raytracer/image/image.hpp"

namespace sweeptrace {

// Where the per-pixel differences are taken.
enum class DiffSpace {
    Display,  // clamped to [0, 1] and sRGB-encoded: what a PNG holds and a viewer sees (default)
    Linear,   // linear radiance as stored, unclamped (for HDR .pfm/.exr)
};

struct DiffOptions {
    DiffSpace space = DiffSpace::Display;
    // A pixel "differs" when its largest channel difference exceeds this (in `space` units;
    // 0.1 in display space is about 25 of 255 steps, far above 8-bit rounding).
    double pixel_threshold = 0.1;
};

struct DiffMetrics {
    int width = 0, height = 0;
    double rmse = 0.0;            // over all pixels and channels
    double psnr = 0.0;            // 20 log10(psnr_peak / rmse) dB; +inf for identical images
    // Display space: 1. Linear: max(1, largest finite channel value of either image), as
    // OpenImageIO's idiff does, so an HDR image's PSNR is not measured against a peak of 1.
    double psnr_peak = 1.0;
    double mean_abs = 0.0;        // mean |a - b| over pixels and channels
    double max_abs = 0.0;         // largest |a - b| of any channel
    int max_x = 0, max_y = 0;     // where it is
    double share_over = 0.0;      // share of pixels whose largest channel difference > pixel_threshold
    // Simplified perceptual difference (NOT NVIDIA's FLIP): both images blurred by a Gaussian of
    // sigma 1 px (detail finer than that is noise a viewer does not resolve at 1:1), converted to
    // CIELAB (D65), CIE76 delta E per pixel. 2.3 is the usual just-noticeable difference.
    double mean_delta_e = 0.0;
    double share_delta_e_over_jnd = 0.0;
    std::size_t non_finite_a = 0, non_finite_b = 0;  // NaN/inf pixels (any channel) in each input
};

// Throws InputError when the sizes differ (naming both sizes).
DiffMetrics compare_images(const Image& a, const Image& b, const DiffOptions& options = {});

// False colour of each pixel's largest channel difference: black at 0 through blue, cyan, green,
// yellow to red at `scale` and above; non-finite pixels are magenta.
Image difference_heatmap(const Image& a, const Image& b, const DiffOptions& options, double scale);

// Noise-aware comparison of a Monte Carlo render against a reference (a golden image or an
// analytic image), the criterion of the image and convergence tests. Linear radiance, unclamped,
// averaged over block x block pixel blocks, per channel, over the pixels that take part. For each
// block and channel
//   excess = max(0, |mean(actual) - mean(reference)| - mean(deterministic bound))
//   z      = excess / sqrt(sum over pixels of max(Var_actual, Var_null) * (1 + reference_noise_ratio)) * count
// Var_actual is the render's own estimate of its pixel means' variance; Var_null (optional) the
// variance the render's pixel means should have if it is correct, from the reference's sample
// variance. The larger of the two per pixel guards both ways against rare, bright paths: those
// the render happened to catch inflate its own estimate, those it happened to miss are in the
// reference's. Pixels are independent, so a block mean's variance is the sum over count^2.
// The deterministic bound per pixel is the 8-bit rounding of a PNG reference (half a code step
// through the sRGB curve) plus relative_tolerance x |reference|. A PNG reference channel at 255
// only says "1 or more": there the test is one-sided (only a render below 1 differs).
// The render is rejected when any z exceeds `z_limit`, by default the two-sided normal quantile
// for a family-wise false-alarm rate `false_alarm` over all tested blocks and channels
// (Bonferroni).
struct BlockTestOptions {
    int block = 8;
    bool golden_is_8bit = true;          // reference is an 8-bit sRGB PNG (see above)
    double reference_noise_ratio = 0.0;  // Var(reference) / Var(actual), e.g. spp_actual / spp_golden
    double relative_tolerance = 0.0;     // deterministic allowance, e.g. float rounding of an analytic value
    double false_alarm = 1e-4;
    double z_limit = 0.0;                // 0 = derive from false_alarm
    const std::vector<std::uint8_t>* mask = nullptr;  // optional: 0 = leave this pixel out
    const Image* null_variance = nullptr;             // optional Var_null per pixel (see above)
};

struct BlockTestResult {
    int blocks_x = 0, blocks_y = 0;
    std::size_t blocks_tested = 0;     // blocks with at least one pixel taking part
    double z_limit = 0.0;
    double max_z = 0.0;                // worst block and channel
    int worst_bx = 0, worst_by = 0, worst_channel = 0;
    double worst_difference = 0.0;     // mean(actual) - mean(reference) there
    double worst_sigma = 0.0;
    std::size_t blocks_over = 0;       // blocks with any channel over the limit
    std::vector<double> block_z;       // per block (row-major), largest over channels; -1 if not tested
    bool pass() const { return max_z <= z_limit; }
    std::string summary() const;
};

BlockTestResult block_test(const Image& reference, const Image& actual, const Image& actual_variance,
                           const BlockTestOptions& options = {});

// False colour of a block test, one block per `block` x `block` pixels: black at z = 0 to red at
// twice the limit (so the limit itself is green-yellow); blocks not tested are dark grey.
Image block_z_heatmap(const BlockTestResult& result, int width, int height, int block);

// Two independent renders of the same thing (equal spp, different seeds) -> their mean and the
// per-pixel variance of that mean, estimated as (a - b)^2 / 4 (E[(a-b)^2] = 2 Var(a) = 4 Var(mean)).
// A one-degree-of-freedom estimate per pixel; block_test pools block x block of them.
struct MeanAndVariance {
    Image mean, variance;
};
MeanAndVariance combine_halves(const Image& a, const Image& b);

// The two-sided standard normal quantile: z with P(|Z| > z) = p. Accurate to ~1e-9 by bisection
// on erfc (monotone), for p in (0, 1).
double normal_two_sided_quantile(double p);

}  // namespace sweeptrace

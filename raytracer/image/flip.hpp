#pragma once
// FLIP, the perceptual difference of an image flipped back and forth with its reference
// (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom, Fairchild, "FLIP: A Difference Evaluator
// for Alternating Images", HPG 2020), and HDR-FLIP (Andersson, Nilsson, Shirley, Akenine-Moller,
// "Visualizing Errors in Rendered High Dynamic Range Images", Eurographics 2021 short paper; also
// "Visualizing and Communicating Errors in Rendered Images", Ray Tracing Gems II, 2021).
// Implemented from the papers' formulas; docs/flip.md restates every formula and constant.
//
// Per pixel, in [0, 1]: 0 = no visible difference, 1 = the largest (e.g. green against blue).
// LDR inputs are linear RGB clamped to [0, 1] (a PNG's sRGB is decoded by read_image). HDR inputs
// are linear radiance: each is exposed at a range of exposures computed from the reference,
// tone mapped (ACES fit by default), clamped, compared by LDR-FLIP, and the per-pixel maximum kept.
// Borders: every filter clamps coordinates to the image (edge pixels repeat).
// Accuracy: evaluated in double; the pipeline has no iterative step, so the result is within
// a few ulp of float of the formulas. FLIP's own implementation computes in float: the same
// formulas run in float32 differed from double by up to 7e-5 per pixel and 5e-7 on the mean on
// the project's 128-px goldens (docs/flip.md, "Checked against the reference implementation").
#include <limits>
#include <numbers>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/image/image.hpp"

namespace sweeptrace {

enum class FlipToneMapper {
    Aces,      // Narkowicz's fit of ACES with FLIP's 0.6 input scale (HDR-FLIP's default)
    Reinhard,  // c / (1 + L): every channel divided by 1 + the pixel's luminance L (hue kept)
};

struct FlipOptions {
    // Pixels per degree of visual angle for the paper's viewing setup, a 0.7 m wide 3840-pixel
    // monitor seen from 0.7 m: 0.7 (3840 / 0.7) pi / 180 = 67.0206. The paper rounds it to 67;
    // FLIP's reference tool uses the unrounded value, and so does this default.
    double pixels_per_degree = 0.7 * (3840.0 / 0.7) * std::numbers::pi / 180.0;
    bool hdr = false;
    FlipToneMapper tone_mapper = FlipToneMapper::Aces;
    // HDR: exposure range in stops; NaN = from the reference as HDR-FLIP computes it.
    double start_exposure = std::numeric_limits<double>::quiet_NaN();
    double stop_exposure = std::numeric_limits<double>::quiet_NaN();
    int exposures = 0;  // 0 = max(2, ceil(stop - start))
};

struct FlipResult {
    int width = 0, height = 0;
    std::vector<float> error;  // per pixel, row-major, in [0, 1]
    double mean = 0.0;
    // Weighted by the error itself (FLIP's pooling): over the errors sorted ascending, the first e
    // at which the running sum exceeds (strictly) the given share of the total error.
    double weighted_median = 0.0, weighted_first_quartile = 0.0, weighted_third_quartile = 0.0;
    double max = 0.0;
    int max_x = 0, max_y = 0;
    double start_exposure = 0.0, stop_exposure = 0.0;  // HDR only
    int exposures = 0;                                  // HDR only; 0 for LDR
};

// Throws InputError when the sizes differ or pixels_per_degree is not positive.
// Non-finite input pixels count as 0 (the caller reports them separately).
FlipResult flip(const Image& reference, const Image& test, const FlipOptions& options = {});

// The building blocks, public so tests can check each against a hand-derived value.
namespace flip_detail {

// The colour term of one pixel pair already spatially filtered: HyAB of Hunt-adjusted CIELAB,
// raised to q_c = 0.7 and remapped to [0, 1] (p_c = 0.4, p_t = 0.95). Linear RGB in [0, 1].
double color_error(const glm::dvec3& reference_rgb, const glm::dvec3& test_rgb);

// The feature term per pixel from the achromatic channels y in [0, 1] (Y / Yn):
// (max(|edge_r| - |edge_t|, |point_r| - |point_t|) / sqrt 2)^q_f with q_f = 0.5.
std::vector<double> feature_error(const std::vector<double>& reference_y, const std::vector<double>& test_y,
                                  int width, int height, double pixels_per_degree);

// The 1-D kernels of the feature filters, index i <-> offset i - radius: the x factor of the edge
// filter (-x g, positive and negative weights each normalised to sum to +1 / -1), of the point
// filter ((x^2/sigma^2 - 1) g, normalised the same way) and the Gaussian y factor (sum 1).
struct FeatureKernels {
    int radius = 0;
    double sigma = 0.0;  // pixels
    std::vector<double> edge, point, gauss;
};
FeatureKernels feature_kernels(double pixels_per_degree);

// HDR-FLIP's exposure range from the reference's luminance (see docs/flip.md).
void automatic_exposures(const Image& reference, FlipToneMapper tone_mapper, double& start, double& stop);
// The tone curve t(x) on a grey value x (both mappers), from which the exposure range is solved.
double tone_map(double x, FlipToneMapper tone_mapper);
// The tone mapper on a linear RGB pixel: ACES per channel, Reinhard through the pixel's luminance.
glm::dvec3 tone_map(const glm::dvec3& rgb, FlipToneMapper tone_mapper);
// HDR-FLIP's luminance, the Rec. 709 weights at four digits (0.2126, 0.7152, 0.0722).
double luminance(const glm::dvec3& rgb);

// Mean, weighted percentiles and maximum of r.error (r.width set), as FlipResult describes them.
void pool(FlipResult& r);

}  // namespace flip_detail
}  // namespace sweeptrace

namespace sweeptrace {

// The largest mean FLIP over any window x window block of pixels (clipped to the image): a
// defect covering a few pixels shows here long before it moves the image's mean.
double flip_largest_window_mean(const FlipResult& result, int window);

// FLIP map in false colour (black 0, blue, cyan, green, yellow, red at 1), linear RGB.
Image flip_heatmap(const FlipResult& result);

}  // namespace sweeptrace

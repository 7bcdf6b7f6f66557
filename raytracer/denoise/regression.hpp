#pragma once
// NFOR's collaborative first-order regression (Bitterli et al. 2016, section 5.2): around every
// pixel c, the colour of its (2R + 1)^2 window is fitted, by weighted least squares, as an affine
// function of the pixel offset and the features (each taken relative to c's), with NL-means
// weights computed on a guide image (the other half buffer: its noise is independent of the
// colour being fitted, so the weights do not follow the noise). Every window's fit predicts all
// of its pixels, and a pixel's result is the weighted mean of the predictions of the windows
// that hold it ("collaborative"). Features that explain an edge (a normal turning, an albedo
// changing) let the fit keep it; the weights keep what the features do not explain.
#include <vector>

#include "raytracer/denoise/nl_means.hpp"
#include "raytracer/denoise/planes.hpp"

namespace sweeptrace::denoise {

struct RegressionParams {
    int patch_radius = 3;    // F of the NL-means weights
    int search_radius = 9;   // R: windows of (2R + 1)^2 pixels
    float variance_scale = 2.0f;  // as NlMeansParams: 2 for a half buffer's guide
};

// `image` (3 channels) regressed on `features` (any channels, at most kMaxRegressionTerms - 3),
// weighted by `guide` (3 channels) and its variance of the mean `guide_variance`, once per
// weight bandwidth k of `bandwidths` (NlMeansParams::k: the candidate filters differ in it), the
// results in that order. The patch distances, which depend on k only through a factor 1 / k^2,
// are computed once for all. Parallel over tiles of window centres; each tile's predictions are
// summed into the result in tile order: bit-identical at any thread count.
std::vector<Planes> collaborative_regression(const Planes& image, const Planes& guide, const Planes& guide_variance, const Planes& features,
                                             const RegressionParams& params, const std::vector<float>& bandwidths, FilterIsa isa);

}  // namespace sweeptrace::denoise

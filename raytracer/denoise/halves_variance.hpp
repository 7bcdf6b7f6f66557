#pragma once
// The variance of a pixel mean as the two half buffers show it. The renderer's variance of the
// mean (the samples' spread over their count) is exact for independent samples, but the
// sobol-halves sampler stratifies each half (docs/aovs.md), so a half's mean varies less than
// its samples' spread says: over the edge test's scene half as much, and a third at its edges
// (docs/denoising.md). NFOR's patch distances divide by the variance, so an overstated one
// makes every candidate filter wider than its bandwidth k means. The halves are independent, so
// (even - odd)^2 / 4 is an unbiased estimate of the mean's variance, but of one degree of
// freedom; the sample variance is steady but of the wrong scale. As Rousselle, Knaus and Zwicker
// (2012) combine the two: the sample variance times the ratio of the two summed over the pixel's
// neighbourhood, which keeps the sample variance's per-pixel detail at the halves' scale.
#include "raytracer/denoise/nfor.hpp"
#include "raytracer/denoise/planes.hpp"

namespace sweeptrace::denoise {

// Per pixel and channel: variance x sum (even - odd)^2 / 4 / sum variance, the sums over the
// (2 radius + 1)^2 window around the pixel (clipped to the image); the variance unchanged (0)
// where the window's sum of it is 0. In one fixed order: the same bits on every run.
Planes halves_variance(const Buffers& buffers, int radius);

}  // namespace sweeptrace::denoise

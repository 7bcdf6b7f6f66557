// The NFOR pipeline (nfor.hpp). The parameters are the paper's, as Tungsten's implementation
// sets them: features prefiltered with 7x7 patches in 11x11 windows at k = 0.5; regression
// windows of 19x19 with 7x7 patches; candidates k = 0.5 and 1.0; error and selection maps
// smoothed with 3x3 patches in 19x19 windows at k = 1; the second pass's features with 7x7
// patches in 5x5 windows at k = 0.5.
#include "raytracer/denoise/nfor.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "raytracer/denoise/halves_variance.hpp"
#include "raytracer/denoise/nl_means.hpp"
#include "raytracer/denoise/regression.hpp"
#include "raytracer/denoise/tiles.hpp"

namespace sweeptrace::denoise {
namespace {

const std::vector<float> kCandidateK{0.5f, 1.0f};
constexpr int kRegressionRadius = 9;  // windows of 19x19 pixels
constexpr std::size_t kChunk = 16384;  // the pixels of a parallel chunk of the per-pixel loops

// The mean of two buffers and, as its variance of the mean, a quarter of their squared
// difference: the two-sample estimate for two independent estimates of the same value. Written
// over the two buffers themselves (mean into `a`, variance into `b`; each element read before it
// is written): at 1920x1080 a fresh pair of whole-image buffers is zero-filled and page-faulted
// in (the profile's clear_page), where the halves are no longer needed after this.
std::pair<Planes, Planes> mean_and_variance(Planes&& a, Planes&& b) {
    for_each_chunk(a.data.size(), kChunk, [&](std::size_t i0, std::size_t i1) {
        for (std::size_t i = i0; i < i1; ++i) {
            const float x = a.data[i], y = b.data[i];
            const float d = y - x;
            a.data[i] = 0.5f * (x + y);
            b.data[i] = 0.25f * d * d;
        }
    });
    return {std::move(a), std::move(b)};
}

}  // namespace

Planes nfor(const NforInput& in, FilterIsa isa) {
    // 0. The variances at the halves' own scale (halves_variance.hpp), over the regression's
    // window: the renderer's sample variance overstates a stratified half's.
    const Buffers& color = in.color;
    const Buffers& features = in.features;
    const Planes color_var = halves_variance(color, kRegressionRadius);

    // 1. Feature prefiltering: each half guided by the other.
    Planes features_even, features_odd;
    {
        const Planes features_var = halves_variance(features, kRegressionRadius);
        const NlMeansParams prefilter{3, 5, 0.5f, 2.0f};
        features_even = nl_means(features.even, features.odd, features_var, prefilter, isa);
        features_odd = nl_means(features.odd, features.even, features_var, prefilter, isa);
    }

    // 2. Each half's colour regressed on the other half's features, weighted on the other half's
    // colour, per candidate bandwidth; 3. its error estimated from the halves.
    const RegressionParams regression{3, kRegressionRadius, 2.0f};
    std::vector<Planes> candidate_even = collaborative_regression(color.even, color.odd, color_var, features_odd, regression, kCandidateK, isa);
    std::vector<Planes> candidate_odd = collaborative_regression(color.odd, color.even, color_var, features_even, regression, kCandidateK, isa);
    // Both candidates' error maps in one image (channels 3k .. 3k + 2: candidate k), smoothed
    // together: they share the guide, and so the weights.
    Planes error, select;
    {
        const std::size_t n = color.mean.data.size();
        Planes noisy_error(color.mean.width, color.mean.height, 6);
        for_each_chunk(n, kChunk, [&](std::size_t i0, std::size_t i1) {
            for (int k = 0; k < 2; ++k)
                for (std::size_t i = i0; i < i1; ++i) {
                    // The even half's filtered value against the odd half's noisy one: the squared
                    // difference overestimates the error by the odd half's variance (twice the
                    // full mean's), and the same the other way; the two filtered halves' own
                    // spread is taken out too.
                    const float v2 = 2.0f * color_var.data[i];
                    const float de = color.odd.data[i] - candidate_even[k].data[i], dodd = color.even.data[i] - candidate_odd[k].data[i];
                    const float spread = candidate_odd[k].data[i] - candidate_even[k].data[i];
                    noisy_error.data[std::size_t(k) * n + i] = 0.5f * ((de * de - v2) + (dodd * dodd - v2)) - 0.25f * spread * spread;
                }
        });
        error = nl_means(noisy_error, color.mean, color_var, {1, 9, 1.0f, 1.0f}, isa);
        // The selection is written over the noisy error maps (no longer needed): no fresh buffer.
        select = std::move(noisy_error);
        select.channels = 3;
        select.data.resize(n);
    }
    // Selection: 1 where the wider candidate's error is smaller, smoothed like the error maps.
    for_each_chunk(select.data.size(), kChunk, [&](std::size_t i0, std::size_t i1) {
        for (std::size_t i = i0; i < i1; ++i) select.data[i] = error.data[i] < error.data[select.data.size() + i] ? 0.0f : 1.0f;
    });
    select = nl_means(select, color.mean, color_var, {1, 9, 1.0f, 1.0f}, isa);
    // Each half's result over its first candidate (each element read before it is written).
    for_each_chunk(select.data.size(), kChunk, [&](std::size_t i0, std::size_t i1) {
        float* even = candidate_even[0].data.data();
        float* odd = candidate_odd[0].data.data();
        for (std::size_t i = i0; i < i1; ++i) {
            const float s = select.data[i];
            even[i] = even[i] + s * (candidate_even[1].data[i] - even[i]);
            odd[i] = odd[i] + s * (candidate_odd[1].data[i] - odd[i]);
        }
    });
    Planes result_even = std::move(candidate_even[0]), result_odd = std::move(candidate_odd[0]);
    candidate_even.clear();
    candidate_odd.clear();
    error = Planes();

    // 4. Second pass: the halves' mean, regressed on the halves' mean features (lightly
    // filtered), with the halves' spread as the variance of both.
    auto [feature_mean, feature_variance] = mean_and_variance(std::move(features_even), std::move(features_odd));
    const Planes final_features = nl_means(feature_mean, feature_mean, feature_variance, {3, 2, 0.5f, 1.0f}, isa);
    feature_mean = feature_variance = Planes();
    const auto [color_mean, color_variance] = mean_and_variance(std::move(result_even), std::move(result_odd));
    Planes result = std::move(collaborative_regression(color_mean, color_mean, color_variance, final_features, {3, kRegressionRadius, 2.0f}, {1.0f}, isa)[0]);
    // Radiance is never negative, but a first-order fit across a bright edge overshoots below 0
    // beside it (the dark surround of an emitter line, measured in docs/denoising.md). Moving a
    // negative value to 0 brings it closer to any non-negative truth, so it only lowers the error.
    for_each_chunk(result.data.size(), kChunk, [&](std::size_t i0, std::size_t i1) {
        for (std::size_t i = i0; i < i1; ++i) result.data[i] = std::max(result.data[i], 0.0f);
    });
    return result;
}

std::uint64_t nfor_memory_bytes(int width, int height, int feature_channels, int threads) {
    // Whole-image float channels alive at once, at the heaviest step (the odd half's candidate
    // regressions): the prefiltered features of both halves (2m), the even half's two candidates
    // (6) and the regression's two results (6); the error maps then hold 12 + 6 + 6, the second
    // pass at most 4m + 12. 4m + 20 bounds them all, and the colour's variance at the halves' scale
    // (3) is alive throughout. Before them, the features' (m) and halves_variance's five double
    // sums (10) beside the prefilter's 2m. Beside the channels, the regression's tiles'
    // accumulation buffers, kept until all tiles are done: per bandwidth 4 channels (3 colours and
    // the weights) over the tile grown by R = 9, (32 + 18)^2 pixels at most.
    const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
    const std::uint64_t channels = 4 * std::uint64_t(feature_channels) + 23;
    const std::uint64_t tiles = std::uint64_t((width + kTileSize - 1) / kTileSize) * std::uint64_t((height + kTileSize - 1) / kTileSize);
    const std::uint64_t grown = std::uint64_t(kTileSize + 2 * kRegressionRadius) * (kTileSize + 2 * kRegressionRadius);
    const std::uint64_t tile_buffers = tiles * kCandidateK.size() * 4 * grown;
    // Per thread: a regression tile's distances (19^2 offsets x 32^2 centres), the weights of one
    // row of its centres for the two bandwidths fitted together (2 x 19^2 x 32), and its copy of the features and colour over the tile grown by 9 ((m + 3) x 50^2), or an
    // NL-means tile's sums, sums of weights and distances (image channels, at most max(m, 6) for
    // the error maps, and twice the guide's, over 64^2 pixels), with the patch scratch, a window
    // row's terms and predictions and a row's normal equations (below 128 KiB).
    const std::uint64_t tile = std::uint64_t(kTileSize) * kTileSize;
    const std::uint64_t nl_means_tile = std::uint64_t(kNlMeansTileSize) * kNlMeansTileSize;
    const std::uint64_t channels_max = std::uint64_t(std::max(feature_channels, 3));
    const std::uint64_t per_thread =
        (19 * 19 * tile + 2 * 19 * 19 * std::uint64_t(kTileSize) + (channels_max + 3) * grown +
         (std::max<std::uint64_t>(channels_max, 6) + 2 * channels_max) * nl_means_tile) * sizeof(float) +
        (128u << 10);
    return (pixels * channels + tile_buffers) * sizeof(float) + std::uint64_t(std::max(threads, 1)) * per_thread;
}

}  // namespace sweeptrace::denoise

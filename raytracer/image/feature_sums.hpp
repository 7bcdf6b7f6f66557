#pragma once
// Feature outputs (AOVs, `render --aovs`): per pixel, the colour and three features of every
// camera sample (albedo, shading normal, position at its first non-specular vertex:
// render/film/sample_features.hpp says how that vertex is found and what a miss or an emitter gives),
// summed exactly (fixed point; squares in square_sum.hpp) and split into two halves by the parity
// of the sample's index, so that a feature-based denoiser (NFOR) gets the two half buffers it
// estimates its error from, and so that farm parts of a render merge into the very numbers one
// machine sums: every sum here is an integer.
//
// Half h of a pixel holds its samples of index i with i % 2 == h: even samples 0, 2, 4, ... and
// odd ones 1, 3, 5, ... of the pixel's own sequence (under adaptive sampling, its own count).
// The full sums are the two halves added; variances are of the full mean, per channel (depth:
// the position's z only).
//
// Widths. The colour is summed as the pixel's colour sum is (partial_sum.hpp: 2^-56, 128 bits;
// squares 256 bits), so its halves add up to that sum exactly. The features are on a coarser
// grid, 2^-kFeatureFractionBits = 2^-32 (a float of magnitude 2^-9 or more is a multiple of it, so
// nearly every value is kept exactly; smaller ones move by at most 2^-33), and sized by their
// range, because a sample's cost is in converting, adding and squaring 12 values:
//   albedo in [0, 1] and normal in [-1, 1]: a sample is at most 2^32, so 2^31 samples sum below
//     2^63 (int64) and their squares below 2^95 (128 bits);
//   position: not bounded by anything but the scene, so its sums stay 128 bits and its depth's
//     squares 256 bits; clamped to +-kFeaturePositionLimit = 2^30 scene units (a sample below
//     2^62, so it converts and squares by the 64-bit paths), far beyond any scene whose float
//     hits are still precise to a unit.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/image/image.hpp"
#include "raytracer/image/partial_sum.hpp"
#include "raytracer/image/square_sum.hpp"

namespace sweeptrace {

// What one camera sample saw where its path first met a non-specular surface.
struct SampleFeatures {
    glm::vec3 albedo{0.0f};
    glm::vec3 normal{0.0f};    // world space, unit, facing the ray that arrived (0 for a miss)
    glm::vec3 position{0.0f};  // camera space: x right, y up, z along the view axis (the depth); 0 for a miss
};

inline constexpr int kFeatureFractionBits = 32;
inline constexpr float kFeaturePositionLimit = 0x1p30f;

// R, G, B or X, Y, Z of a bounded feature on the 2^-32 grid.
struct BoundedSum {
    std::int64_t v[3] = {0, 0, 0};
    bool operator==(const BoundedSum&) const = default;
};

struct FeatureSums {
    // [0]: even samples, [1]: odd samples. Colour in 2^-56, the features in 2^-32.
    PixelSum color[2], position[2];
    BoundedSum albedo[2], normal[2];
    // Of all samples: colour R, G, B and depth (position z), 256 bits; albedo R, G, B and
    // normal X, Y, Z, 128 bits.
    SquareSum color_square[3], depth_square;
    SumUInt bounded_square[6] = {0, 0, 0, 0, 0, 0};
    std::int32_t count[2] = {0, 0};

    FeatureSums& operator+=(const FeatureSums& o);
    bool operator==(const FeatureSums&) const = default;
};

// A camera sample as the feature sums take it: its colour (the value the pixel's colour sum
// takes, after filter weight and clamps: a colour clamped to kSampleLimit is counted where it
// joins that sum) and its features.
struct FeatureSample {
    glm::vec3 color{0.0f};
    SampleFeatures features;
};

// Adds the camera sample of index `sample` (its parity picks the half).
void add_feature_sample(FeatureSums& sums, std::int64_t sample, const FeatureSample& fs);

// Adds n <= kFeatureBatch camera samples of consecutive indices first, first + 1, ...: the same
// sums as add_feature_sample of each, with each sum stored once rather than once a sample (a
// pixel's pending samples: render/renderer.cpp).
inline constexpr int kFeatureBatch = 4;
void add_feature_samples(FeatureSums& sums, std::int64_t first, const FeatureSample* samples, int n);

// The feature images of a render, all width x height, means over each pixel's own samples.
struct FeatureLayers {
    int width = 0, height = 0;
    Image color, color_variance;  // colour mean and the variance of that mean
    Image albedo, albedo_variance;
    Image normal, normal_variance;
    Image position;
    std::vector<float> depth_variance;  // of position z
    // [0]: even samples' means, [1]: odd samples'.
    std::array<Image, 2> half_color, half_albedo, half_normal, half_position;
};

// `sums` row-major, width * height.
FeatureLayers feature_layers(const std::vector<FeatureSums>& sums, int width, int height);
// The same for `rows` rows of `width` pixels whose sums start at `sums`, into `layers`, whose
// images become width x rows (their storage kept when they are that size already): the feature
// EXR is written from the sums a block of rows at a time (feature_exr.hpp), so a render never
// holds its whole layers.
void fill_feature_layers(const FeatureSums* sums, int width, int rows, FeatureLayers& layers);

// Farm parts (partial_image.hpp) store a pixel's FeatureSums as kFeatureWords 32-bit words, each
// in a UINT channel named feature_word_names()[k]: the four 128-bit half sums of three channels,
// the four 64-bit ones, the two counts, four 256-bit squares and six 128-bit ones.
inline constexpr int kFeatureWords = 4 * 3 * 4 + 4 * 3 * 2 + 2 + 4 * 8 + 6 * 4;
const std::vector<std::string>& feature_word_names();
void feature_to_words(const FeatureSums& sums, std::uint32_t* words);
FeatureSums feature_from_words(const std::uint32_t* words);

}  // namespace sweeptrace

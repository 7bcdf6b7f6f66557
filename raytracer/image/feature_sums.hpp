#pragma once
// Feature outputs (AOVs, `render --aovs`): per pixel, the colour and three features of every
// camera sample (albedo, shading normal, position at its first non-specular vertex:
// render/film/sample_features.hpp says how that vertex is found and what a miss or an emitter gives),
// summed exactly (fixed point, partial_sum.hpp; squares in square_sum.hpp) and split into two
// halves by the parity of the sample's index, so that a feature-based denoiser (NFOR) gets the
// two half buffers it estimates its error from, and so that farm parts of a render merge into
// the very numbers one machine sums: every sum here is an integer.
//
// Half h of a pixel holds its samples of index i with i % 2 == h: even samples 0, 2, 4, ... and
// odd ones 1, 3, 5, ... of the pixel's own sequence (under adaptive sampling, its own count).
// The full sums are the two halves added; variances are of the full mean, per channel (depth:
// the position's z only).
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

struct FeatureSums {
    // [0]: even samples, [1]: odd samples.
    PixelSum color[2], albedo[2], normal[2], position[2];
    std::int32_t count[2] = {0, 0};
    // Of all samples: colour R, G, B; albedo R, G, B; normal X, Y, Z; depth (position z).
    static constexpr int kSquares = 10;
    SquareSum square[kSquares];

    FeatureSums& operator+=(const FeatureSums& o);
    bool operator==(const FeatureSums&) const = default;
};

// Adds the sample of index `sample` (its parity picks the half) with colour `color` (the value the
// pixel's colour sum takes, after filter weight and clamps) and features `f`. `clamped`: some
// value was beyond kSampleLimit and was clamped to it (as add_sample says).
void add_feature_sample(FeatureSums& sums, std::int64_t sample, const glm::vec3& color, const SampleFeatures& f,
                        bool& clamped);

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

// Farm parts (partial_image.hpp) store a pixel's FeatureSums as kFeatureWords 32-bit words, each
// in a UINT channel named feature_word_names()[k].
inline constexpr int kFeatureWords = 8 * 3 * 4 + 2 + FeatureSums::kSquares * 8;
const std::vector<std::string>& feature_word_names();
void feature_to_words(const FeatureSums& sums, std::uint32_t* words);
FeatureSums feature_from_words(const std::uint32_t* words);

}  // namespace sweeptrace

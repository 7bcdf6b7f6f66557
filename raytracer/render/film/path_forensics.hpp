#pragma once
// Noise forensics (issue 34 item 1): which kinds of light path carry the noise of each region of
// the image. Every contribution a sample adds (an emitter hit, a light sample, an escaped ray) is
// tagged with
//   - its path type in Heckbert's notation from the light to the eye: L, then one letter per
//     scattering vertex (D diffuse, G glossy: any non-delta lobe that is not Lambertian, S a delta
//     bounce: mirror, glass, V scattering in a medium), then E; "L E" is an emitter seen directly;
//   - the light it came from (an emissive object, a scene light, the environment, or the plain
//     background), named as the scene names it;
//   - the material of the vertex "that made it large": the one with the largest throughput factor
//     along the path, |f cos| / pdf of the sampled direction (for the light sample's own vertex,
//     |f cos| w / pdf of the light sample, w its MIS weight).
//
// Attribution. A sample's value X (luminance, after the pixel filter's weight and film clamps)
// is the sum of its contributions c_k. Two credits per contribution:
//   - variance: c_k (X - m), m the mean of the pixel's samples from the passes before this one.
//     m is independent of this sample, so E[c_k (X - m)] = E[c_k X] - E[c_k] E[X] = Cov(c_k, X),
//     and these covariances add up to Var(X) exactly: each type's share of the pixel's variance,
//     its noise. Credited from the second pass on (the first has no m); a single credit can be
//     negative, the sums over many samples are the covariances. Regions are ranked and coloured
//     by this share.
//   - second moment: c_k X, which sums to X^2 and is never negative; its shares split E[X^2] =
//     Var(X) + E[X]^2, so a bright, smooth type (an emitter seen directly) also ranks high here
//     although it is not noisy: the reason the variance credit is the one used. (Summing c_k^2
//     instead drops the cross terms of two types meeting in one sample and adds up to nothing
//     measurable.)
// Each type's share of the mean, sum c_k, is reported beside them.
//
// Regions are the renderer's 16x16 tiles: a tile is rendered by one thread per pass, so each
// region's sums are added in one fixed order (pixel, then contribution), passes are merged only
// when complete, and the report is the same bit for bit for any thread count.
//
// Bounded: a region keeps the sums of at most kRegionTypes keys (path type, light, material); the
// rest of its credits go to its "other types" key (PathKey::other()), reported as a row of its
// own, so the shares still add up to the whole. Paths that mix D, G and S vertices make new keys
// at every sample (a 16x16 region of staircase2 meets 250 in 16 spp), and with every key kept the
// memory grew with the spp: 240 MB for a 16x16 image at 256 spp. Which keys stay: a pass's keys
// in the order met, up to kRegionTypes (more go to "other"); when the pass joins the totals, a new
// key takes the place of the kept key with the smallest second moment if its own in that pass is
// larger, the replaced key's sums going to "other", else its sums go there. A key's variance
// credits are at most its second-moment credits (both are sums of c_k times X or X - m, c_k and X
// >= 0), so a key dropped this way carries less of the variance than the keys kept do of E[X^2].
// The memory of forensics depends on the image's size alone (memory_bytes, charged to the
// render's memory estimate). Recording reads
// the path and draws no random number, so the image is the same with it on or off.
// Off (no PathTally given to the integrator) it costs one pointer test per contribution.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/image/image.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

class LightSet;

// What the path type of one contribution is made of (see the header comment).
struct PathKey {
    std::uint64_t vertices = 0;  // 2 bits per vertex from the eye, 0 V, 1 D, 2 G, 3 S; see kMaxVertices
    std::uint8_t length = 0;     // scattering vertices, capped at kMaxVertices (then "..." is shown)
    std::int32_t light = -1;     // LightSet's light index, kBackground or kMediumEmission
    std::int32_t material = -1;  // Scene::materials index of the largest-factor vertex, -1: none
    static constexpr int kMaxVertices = 30;
    static constexpr std::int32_t kBackground = -2;
    static constexpr std::int32_t kMediumEmission = -3;  // light a participating medium emits
    // A region's credits beyond the keys it keeps (path_forensics.hpp): a length no path has, no
    // one light, no material.
    static constexpr std::uint8_t kOtherLength = 0xff;
    static PathKey other() { return PathKey{0, kOtherLength, -1, -1}; }
    bool is_other() const { return length == kOtherLength; }
    auto operator<=>(const PathKey&) const = default;
};

struct PathMoments {
    double variance = 0.0;  // sum of c_k (X - m), from the second pass on
    double second = 0.0;    // sum of c_k X
    double first = 0.0;     // sum of c_k
};

// One sample's path, as the integrator builds it. One per thread; begin() before each sample.
class PathTally {
public:
    // Medium: a scattering event in a participating medium (letter V; no material).
    enum Kind : std::uint8_t { Medium = 0, Diffuse = 1, Glossy = 2, Specular = 3 };
    static constexpr std::uint32_t kNoMaterial = 0xffffffffu;  // a vertex with no material (-1 in PathKey)
    static Kind kind_of(const MaterialParameters& m, bool delta_lobe);

    void begin() {
        key_ = PathKey{};
        largest_ = -1.0f;
        largest_material_ = -1;
        found_.clear();
    }
    // A vertex scattered the path on (BSDF sample with throughput factor `factor`).
    void scatter(Kind kind, std::uint32_t material, float factor);
    // A contribution `c` ending at `light` (LightSet's index; PathKey::kBackground).
    void add(const glm::vec3& c, std::int32_t light);
    // A light sample's contribution: the current vertex (not yet scattered) is part of its path.
    void add_light_sample(Kind kind, std::uint32_t material, float factor, const glm::vec3& c, std::int32_t light);

    struct Found {
        PathKey key;
        float value = 0.0f;  // luminance of the contribution
    };
    const std::vector<Found>& found() const { return found_; }

private:
    static void push(PathKey& k, Kind kind) {
        if (k.length >= PathKey::kMaxVertices) return;
        k.vertices |= std::uint64_t(kind) << (2 * k.length);
        ++k.length;
    }
    void note_factor(std::uint32_t material, float factor) {
        if (factor > largest_) {
            largest_ = factor;
            largest_material_ = static_cast<std::int32_t>(material);
        }
    }
    void add_with(const PathKey& k, std::int32_t material, const glm::vec3& c, std::int32_t light);

    PathKey key_;
    float largest_ = -1.0f;
    std::int32_t largest_material_ = -1;
    std::vector<Found> found_;
};

// The integrator's hook: records `c` when a tally is on, and returns it.
inline glm::vec3 tally_found(PathTally* tally, const glm::vec3& c, std::int32_t light) {
    if (tally != nullptr) tally->add(c, light);
    return c;
}

// Per-region sums over a render, and the report made from them.
class PathForensics {
public:
    // Keys a region keeps sums for, besides PathKey::other() (the header comment says which).
    static constexpr std::size_t kRegionTypes = 256;

    explicit PathForensics(const Scene& scene) : scene_(scene) {}

    // The most forensics keeps for a width x height render: per region its kept keys' sums, the
    // pass in flight's and the report's image-wide copy of them; per pixel two sums.
    static std::uint64_t memory_bytes(int width, int height);
    // The most keys a region has held (for tests of the bound).
    std::size_t most_region_keys() const;

    // Called by the renderer before the first pass: its tiles are the regions, its lights' names
    // the ones reported.
    void start(int width, int height, int tile_size, const LightSet& lights);
    // A sample of `pixel` in `tile` finished with value `sample` (after filter weight and clamps).
    void finish_sample(int tile, std::size_t pixel, const PathTally& tally, const glm::vec3& sample);
    // The pass all tiles finished joins the totals; a dropped pass is forgotten.
    void end_pass();
    void drop_pass();

    // The names a report uses.
    std::string path_text(const PathKey& k) const;
    std::string light_text(std::int32_t light) const;
    std::string material_text(std::int32_t material) const;

    struct Row {
        std::string path, light, material;
        double variance = 0.0, second = 0.0, first = 0.0;  // shares of the totals
    };
    // Sums over the image: of c_k (X - m) (= sum of X (X - m), samples of the second pass on),
    // of c_k X (= sum of X^2), of c_k (= sum of X), and the samples.
    struct Totals {
        double variance = 0.0, second = 0.0, first = 0.0;
        std::uint64_t samples = 0;
    };
    Totals totals() const;
    // Totals over the image, largest share of the variance first; by_path: path types only.
    std::vector<Row> rows(bool by_path, std::size_t limit) const;
    // The terminal table.
    std::string table(std::size_t limit = 8) const;
    // The JSON document (regions with their top types), written by the caller.
    std::string json(int spp) const;
    // Each region filled with the colour of its dominant path type, over a faint grey copy of
    // `image` (linear); the colours are the JSON's "colour" for each type.
    Image picture(const Image& image) const;

private:
    struct Region {
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        std::uint64_t samples = 0, pending_samples = 0, variance_samples = 0;  // the last: passes 2 on
        std::map<PathKey, PathMoments> totals;   // at most kRegionTypes keys and other()
        std::map<PathKey, PathMoments> pending;  // the pass in flight's, the same bound
    };
    static void merge_pass(Region& r);
    static PathKey path_only(PathKey k) {
        k.light = -1;
        k.material = -1;
        return k;
    }
    std::map<PathKey, PathMoments> image_totals(bool by_path) const;
    std::string dominant(const Region& r) const;
    std::vector<std::string> palette_order() const;

    const Scene& scene_;
    std::vector<std::string> light_names_;
    int width_ = 0, height_ = 0;
    std::vector<Region> regions_;
    std::vector<double> pixel_sum_;   // luminance of the pixel's samples over the completed passes
    std::vector<double> pixel_pass_;  // the pass in flight's sample of each pixel
    int passes_ = 0;                  // completed
    std::size_t most_keys_ = 0;       // the most keys a region has held
};

}  // namespace sweeptrace

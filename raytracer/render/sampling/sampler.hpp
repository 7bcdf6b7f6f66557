#pragma once
// The numbers a camera sample consumes, addressed by (seed, pixel, sample index, dimension), so
// that they never depend on the thread, the tile order or how the sample range is split.
//
// SamplerKind::Sobol (the default): every 1D or 2D slot of the dimension layout below is its own
// Owen-scrambled (0, 2)-sequence (sampler_sobol.hpp), with the sample index shuffled by an
// independent nested uniform scramble per (pixel, slot): Burley 2020's "shuffled scrambled Sobol"
// padding. Within a pixel, the first 2^k samples of each 2D slot form a (0, k, 2)-net and of each
// 1D slot a stratified set (one point in each 1/2^k interval); different slots and different
// pixels are decorrelated by their independent seeds. Each point is uniform on [0, 1)^d for a
// random seed, so every estimator keeps its expectation. Bounces from kSobolBounces on draw
// hashed independent uniforms instead (the fallback), so any max_depth (up to 1024) is served;
// the shipped scenes' max_depth (8-10) never reaches it. Cost: about 10 ns of CPU per 2D slot
// (three hash permutations), against ~2 ns for a PCG pair; measured in docs/sampling.md as the
// CPU time of whole renders.
// SamplerKind::Independent: the per-sample PCG32 stream of random.hpp, consumed in call order
// (dimensions ignored): exactly the renderer's samples before the Sobol sampler existed.
// Two streams per (seed, pixel, sample): the camera sample's, and vcm's light subpath's
// (SamplerStream::LightSubpath), which vcm traces in a pass of its own and then joins to the camera
// subpath. The Sobol sampler keeps them apart by dimension (bdpt.cpp gives the camera subpath the
// odd bounce slots and the light subpath the even ones), so its light stream is the camera's, and
// bdpt, which draws both subpaths in one call, consumes one stream; the independent sampler
// ignores dimensions, so with one stream vcm's camera subpath replayed the numbers of the light
// subpath it joins (test_render_vcm_streams.cpp).
#include <cstdint>

#include <glm/vec2.hpp>

#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/sampler_sobol.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// The fixed dimension order of a path. The camera takes dimensions 0-3; bounce b (b = 0 at the
// first surface hit) takes kCameraDims + b * kBounceDims + slot. A 2D slot covers two dimensions.
// The shutter time has dimension kTime = -1, below every other: a 1D Sobol slot of its own that
// no other decision, at any depth, can reach, drawn only when the camera has a shutter, so a scene
// without one takes exactly the numbers it took before motion blur existed (with the Sobol
// sampler a slot's numbers depend only on its dimension, not on what else was drawn; the
// Independent sampler's stream is consumed in call order, and time is drawn after the camera's).
namespace sample_dim {
inline constexpr int kFilm = 0;  // 2D: position inside the pixel
inline constexpr int kLens = 2;  // 2D: point on the thin lens
inline constexpr int kCameraDims = 4;
inline constexpr int kTime = -1;  // 1D: the time in the shutter (render/camera.hpp, shutter_fraction)
inline constexpr int kLightChoice = 0;    // 2D: which light (x) and which triangle / face of it (y)
inline constexpr int kLightPart = 1;      // the y of kLightChoice: each coordinate of a net is stratified
inline constexpr int kLightPoint = 2;     // 2D: the point on it
inline constexpr int kBsdfLobe = 4;       // 1D: reflect or refract, ...
inline constexpr int kBsdfDirection = 5;  // 2D: the direction within the lobe
inline constexpr int kRoulette = 7;       // 1D: Russian roulette
inline constexpr int kGuiding = 8;        // reserved for path guiding (#8): 1D choice + 2D direction
inline constexpr int kBounceDims = 11;
inline constexpr int kSobolBounces = 16;  // bounces 0..15 are stratified, later ones hashed

inline constexpr int bounce(int b, int slot) { return kCameraDims + b * kBounceDims + slot; }
static_assert(kTime < kFilm && kTime < kLens && kTime < bounce(0, 0), "the time slot lies outside the camera's and bounces' ranges");
}  // namespace sample_dim

enum class SamplerStream : std::uint8_t { Camera = 0, LightSubpath = 1 };

class PixelSampler {
public:
    PixelSampler(SamplerKind kind, std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample,
                 SamplerStream stream = SamplerStream::Camera)
        : kind_(kind),
          key_(mix64(mix64(seed ^ 0x243f6a8885a308d3ull) ^ pixel)),
          sample_(sample),
          reversed_sample_(reverse_bits32(static_cast<std::uint32_t>(sample))) {
        if (kind == SamplerKind::Independent) rng_ = Rng(seed, pixel, sample, static_cast<std::uint64_t>(stream));
    }

    // Uniform in [0, 1).
    float get1d(int dim) {
        if (kind_ == SamplerKind::Independent) return rng_.uniform();
        if (dim >= kFirstHashed) return fraction_to_float(static_cast<std::uint32_t>(hashed(dim)));
        const SlotSeeds s = slot_seeds(dim);
        return fraction_to_float(scrambled_sobol_dim0(s.index, s.x));
    }

    // Uniform in [0, 1)^2; `dim` and dim + 1 are taken.
    glm::vec2 get2d(int dim) {
        if (kind_ == SamplerKind::Independent) {
            const float u = rng_.uniform();
            return {u, rng_.uniform()};
        }
        if (dim >= kFirstHashed) {
            const std::uint64_t h = hashed(dim);
            return {fraction_to_float(static_cast<std::uint32_t>(h)), fraction_to_float(static_cast<std::uint32_t>(h >> 32))};
        }
        const SlotSeeds s = slot_seeds(dim);
        return {fraction_to_float(scrambled_sobol_dim0(s.index, s.x)),
                fraction_to_float(scrambled_sobol_dim1(s.index, s.y))};
    }

    // A random stream of this pixel sample's own, apart from the dimensions above (drawing from
    // it changes none of them), for estimators that take an unbounded count of numbers: delta
    // and ratio tracking in media (render/media/tracking.hpp). `tag` tells such streams apart.
    Rng stream(std::uint64_t tag) const { return Rng(key_, tag, sample_); }

private:
    static constexpr int kFirstHashed = sample_dim::bounce(sample_dim::kSobolBounces, 0);

    struct SlotSeeds {
        std::uint32_t index;  // the shuffled sample index
        std::uint32_t x, y;   // scramble seeds of the slot's two coordinates
    };

    SlotSeeds slot_seeds(int dim) const {
        // One 64-bit hash per slot: its low half shuffles, its high half scrambles x, and the high
        // half of its product with an odd constant (every bit of it a function of all of h's
        // lower bits, not a bitwise copy of x's seed, which would correlate the two coordinates'
        // digit flips and make a single point non-uniform in 2D) scrambles y.
        const std::uint64_t h = mix64(key_ + static_cast<std::uint64_t>(dim));
        const auto hi = static_cast<std::uint32_t>(h >> 32);
        // Sample indices are used mod 2^32: a pixel never takes 4 billion samples.
        const auto index = reverse_bits32(laine_karras_permutation(reversed_sample_, static_cast<std::uint32_t>(h)));
        return {index, hi, static_cast<std::uint32_t>((h * 0xd1342543de82ef95ull) >> 32)};
    }

    std::uint64_t hashed(int dim) const { return mix64(mix64(key_ ^ sample_) ^ static_cast<std::uint64_t>(dim)); }

    SamplerKind kind_;
    Rng rng_;  // Independent only
    std::uint64_t key_;
    std::uint64_t sample_;
    std::uint32_t reversed_sample_;  // bit-reversed sample index mod 2^32, for the shuffle
};

}  // namespace sweeptrace

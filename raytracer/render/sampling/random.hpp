#pragma once
// Per pixel-sample random streams. Every camera sample (seed, pixel, sample index) owns its own
// PCG32 stream (O'Neill 2014), its state and stream selector derived by hashing the triple, so
// the numbers a sample sees do not depend on which thread renders it or in which order: the
// image is identical bit for bit for any thread count or tile order.
#include <cstdint>

namespace sweeptrace {

// SplitMix64's finaliser (Steele et al. 2014): a bijective mix with full avalanche, used only to
// turn the (seed, pixel, sample) triple into well-separated PCG states.
inline std::uint64_t mix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

class Rng {
public:
    Rng() = default;  // a placeholder stream; assign a real one before use
    // `stream` 0 is the camera sample's own stream; another value a second stream of the same
    // (seed, pixel, sample), independent of it (vcm's light subpaths: sampler.hpp).
    Rng(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample, std::uint64_t stream = 0) {
        std::uint64_t h = mix64(mix64(mix64(seed) ^ pixel) ^ sample);
        if (stream != 0) h = mix64(h ^ mix64(stream));
        inc_ = (mix64(h ^ 0x5851f42d4c957f2dull) << 1u) | 1u;  // odd: a valid PCG stream selector
        state_ = 0;
        next_u32();
        state_ += h;
        next_u32();
    }

    std::uint32_t next_u32() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits scaled by 2^-24, so 1 is never returned.
    float uniform() { return static_cast<float>(next_u32() >> 8) * 0x1.0p-24f; }

private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_ = 1;
};

}  // namespace sweeptrace

#pragma once
// Exact per-pixel sums of radiance samples, so that a render split into sample ranges and merged
// gives the very bits one machine gives: integer addition is associative, floating-point addition
// is not, so the renderer and the merge both sum in fixed point and convert to a mean only once.
//
// Each float sample v is rounded to the nearest multiple of 2^-kSumFractionBits (ties to even) and
// added as a signed 128-bit integer. Floats of magnitude >= 2^-33 are multiples of 2^-56 already,
// so they are added exactly; smaller ones (below 1.2e-10, invisible in any image) change by at
// most 2^-57. Samples are clamped to +-kSampleLimit = 2^40 (1.1e12, far above any radiance a
// scene here produces; each clamp is counted like a non-finite sample), so one sample is below
// 2^96 in fixed point and 2^31 samples (more than an int spp can ask for) stay below 2^127: the
// sum cannot overflow.
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

namespace sweeptrace {

// GCC/Clang's 128-bit integers (not ISO C++, hence the marker).
__extension__ typedef __int128 SumInt;
__extension__ typedef unsigned __int128 SumUInt;

inline constexpr int kSumFractionBits = 56;
inline constexpr float kSampleLimit = 0x1p40f;

struct PixelSum {
    SumInt rgb[3] = {0, 0, 0};

    PixelSum& operator+=(const PixelSum& o) {
        for (int c = 0; c < 3; ++c) rgb[c] += o.rgb[c];
        return *this;
    }
    bool operator==(const PixelSum&) const = default;
};

// A float times a power of two (`scaled`, exact in double) as the nearest integer, ties to even
// (the integer nearbyint gives in the default rounding mode), for |scaled| < 2^63, without
// nearbyint's library call or a 128-bit conversion's (feature outputs convert 12 values a
// sample). A float is m 2^e with |m| < 2^24, so `scaled`, m 2^(e + k), is an integer once its
// magnitude reaches 2^24; below 2^51, adding and subtracting 1.5 * 2^52 rounds to the nearest
// integer, ties to even, because the sum lies in [2^52, 2^53), where doubles are the integers,
// and 1.5 * 2^52 is even.
inline std::int64_t nearest_int64(double scaled) {
    if (std::fabs(scaled) < 0x1p51) scaled = (scaled + 0x1.8p52) - 0x1.8p52;
    return static_cast<std::int64_t>(scaled);
}

// One sample in fixed point. `v` must be finite (the renderer replaces non-finite samples by 0
// first); |v| above kSampleLimit is clamped, and `clamped` says so.
inline SumInt to_fixed(float v, bool& clamped) {
    clamped = std::fabs(v) > kSampleLimit;
    const float c = clamped ? std::copysign(kSampleLimit, v) : v;
    // Below 2^62 (|v| < 64, nearly every sample) through int64; above, the integer it already is
    // (nearest_int64), below 2^96, exact in SumInt.
    const double r = static_cast<double>(c) * 0x1p56;
    if (std::fabs(r) < 0x1p62) return nearest_int64(r);
    return static_cast<SumInt>(r);
}

// Whether add_sample clamps a channel of v (and so counts the sample as clamped).
inline bool beyond_sample_limit(const glm::vec3& v) {
    return std::fabs(v.x) > kSampleLimit || std::fabs(v.y) > kSampleLimit || std::fabs(v.z) > kSampleLimit;
}

inline void add_sample(PixelSum& sum, const glm::vec3& v, bool& clamped) {
    clamped = false;
    for (int c = 0; c < 3; ++c) {
        bool k = false;
        sum.rgb[c] += to_fixed(v[c], k);
        clamped = clamped || k;
    }
}

// The mean of `count` samples as the image stores it. One function for the renderer and the merge:
// equal sums and counts give equal bits. The int128 -> double conversion rounds once (to nearest),
// the scale by 2^-56 is exact, the division and the cast to float round once each.
inline glm::dvec3 sum_value(const PixelSum& s) {
    return {static_cast<double>(s.rgb[0]) * 0x1p-56, static_cast<double>(s.rgb[1]) * 0x1p-56,
            static_cast<double>(s.rgb[2]) * 0x1p-56};
}
inline glm::vec3 mean_of(const PixelSum& s, std::int64_t count) {
    if (count <= 0) return glm::vec3(0.0f);
    return glm::vec3(sum_value(s) / static_cast<double>(count));
}

static_assert(kSumFractionBits == 56, "to_fixed and sum_value scale by 2^56 literally");

}  // namespace sweeptrace

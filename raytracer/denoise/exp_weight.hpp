#pragma once
// The NL-means weight exp(-max(d, 0)) of a patch distance d, written without branches or library
// calls so that a loop over a row of pixels vectorizes: NFOR takes one per pixel, neighbour and
// filter (about 8,000 per pixel), and glibc's expf, called one value at a time, was a third of
// the regression's weights. Cody and Waite's reduction e^x = 2^n e^r with |r| <= ln 2 / 2 and a
// degree-6 Taylor polynomial for e^r: relative error below 3e-7 (a few float ulps), far below
// the weights' own noise. Every lane computes the same float operations, so the value does not
// depend on the vector width the compiler picks.
#include <algorithm>
#include <bit>
#include <cstdint>

namespace sweeptrace::denoise {

// Below this exponent e^x is under the smallest normal float (2^-126 = e^-87.34): weight 0, as the
// library's expf gives (to within its subnormal range, where no weight matters).
inline constexpr float kExpWeightUnderflow = -87.0f;

[[gnu::always_inline]] inline float exp_weight(float distance) {
    const float x = std::max(-std::max(distance, 0.0f), kExpWeightUnderflow);
    // n = round(x / ln 2): adding 1.5 x 2^23 (the floats there are 1 apart) rounds to an integer,
    // subtracting it again is exact. (Rounding by int(), or float(int), left GCC a branch that
    // kept the AVX2 loops scalar.)
    constexpr float kRound = 12582912.0f;  // 1.5 x 2^23
    const float nf = (x * 1.44269504f + kRound) - kRound;
    const int n = int(nf);
    // r = x - n ln 2 with ln 2 split in a part exact in float times n and the rest
    const float r = (x - nf * 0.693145752f) - nf * 1.42860677e-6f;
    float p = 1.0f / 720.0f;
    p = p * r + 1.0f / 120.0f;
    p = p * r + 1.0f / 24.0f;
    p = p * r + 1.0f / 6.0f;
    p = p * r + 0.5f;
    p = p * r + 1.0f;
    p = p * r + 1.0f;
    const float scale = std::bit_cast<float>(std::uint32_t(n + 127) << 23);
    return x > kExpWeightUnderflow ? p * scale : 0.0f;
}

}  // namespace sweeptrace::denoise

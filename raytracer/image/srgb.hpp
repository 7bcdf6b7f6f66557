#pragma once
// The sRGB transfer curve (IEC 61966-2-1), exact piecewise form, not a 2.2 power.
// Error bound: both directions are evaluated in double and rounded once to float, so the
// result is within 1 ulp of the float nearest the true value (std::pow is within 1 ulp in
// double; the final rounding dominates).
#include <array>
#include <cmath>

namespace sweeptrace {

// Linear [0, 1] -> encoded [0, 1]. Values outside [0, 1] are clamped (PNG cannot hold them);
// NaN becomes 0 so a broken pixel shows black instead of poisoning a file.
inline float srgb_encode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;  // also catches NaN
    if (linear >= 1.0f) return 1.0f;
    const double c = linear;
    return static_cast<float>(c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055);
}

// Encoded [0, 1] -> linear [0, 1].
inline float srgb_decode(float encoded) {
    if (!(encoded > 0.0f)) return 0.0f;
    if (encoded >= 1.0f) return 1.0f;
    const double c = encoded;
    return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

// Nearest 8-bit code of an encoded value (round half up; the encoded value is already in [0, 1]).
inline unsigned char to_byte(float encoded) {
    return static_cast<unsigned char>(std::lround(static_cast<double>(encoded) * 255.0));
}

// Linear values of the 256 8-bit codes, for the 8-bit readers (PNG, JPEG): one decode per code,
// not per texel.
inline const std::array<float, 256>& srgb_decode_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int v = 0; v < 256; ++v) t[v] = srgb_decode(v / 255.0f);
        return t;
    }();
    return table;
}

}  // namespace sweeptrace

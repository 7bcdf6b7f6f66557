#pragma once
// Floating-point error bounds (Higham's gamma_n, as used by pbrt-v4 §6.8): a value computed with
// n rounded float operations from exact inputs is within gamma(n) * |value| of the exact result.
#include <cmath>
#include <limits>

namespace collision {

inline constexpr float machine_epsilon = std::numeric_limits<float>::epsilon() * 0.5f;

inline constexpr float gamma(int n) { return (n * machine_epsilon) / (1.0f - n * machine_epsilon); }

inline float next_float_up(float v) { return std::nextafter(v, std::numeric_limits<float>::infinity()); }
inline float next_float_down(float v) { return std::nextafter(v, -std::numeric_limits<float>::infinity()); }

}  // namespace collision

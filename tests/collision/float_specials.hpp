#pragma once
// The IEEE special values the tests feed the routines (their contracts for degenerate input say
// what infinity and NaN give): one home, so the test files can share a unity build unit.
#include <limits>

inline constexpr float k_inf = std::numeric_limits<float>::infinity();
inline constexpr float k_nan = std::numeric_limits<float>::quiet_NaN();

#pragma once
// Which instruction set the wide BVH's traversal runs with, chosen at run time from what the
// CPU reports (cpuid through __builtin_cpu_supports), never from the build machine's -march:
// the AVX2 kernels live in their own translation unit compiled for AVX2 by a target pragma, the
// scalar kernels in the baseline ISA. Both give bit-identical results (same float operations in
// the same order; tests/raytracer/test_accel_wide_bvh.cpp checks it).
#include <string>

namespace sweeptrace {

enum class SimdPath { Scalar, Avx2 };

// The fastest path this CPU runs. SWEEPTRACE_SIMD=scalar in the environment forces the scalar
// path (to measure or to rule the SIMD code out); an AVX-512 CPU runs the AVX2 path.
SimdPath default_simd_path();
bool cpu_has_avx2();
std::string simd_path_name(SimdPath path);

}  // namespace sweeptrace

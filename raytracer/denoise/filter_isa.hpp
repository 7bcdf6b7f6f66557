#pragma once
// The instruction set the denoiser's pixel loops run with. The loops are written once, lane by
// lane (no sum runs across lanes, and the build fuses no multiply-add), and compiled twice: for
// the build's baseline ISA and for AVX2, twice the lanes. Both give the same bits (tested). The
// caller picks: sweeptrace asks raytracer/accel/simd_path.hpp (the CPU's cpuid, and
// SWEEPTRACE_SIMD=scalar to force the baseline); the denoiser, a side stage, cannot ask itself.
namespace sweeptrace::denoise {

enum class FilterIsa { Baseline, Avx2 };

}  // namespace sweeptrace::denoise

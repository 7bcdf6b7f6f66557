#pragma once
// The instruction set the denoiser's pixel loops run with. The loops are written once, lane by
// lane (no sum runs across lanes, and the build fuses no multiply-add: -ffp-contract=off), and
// compiled three times: for the build's baseline ISA, for AVX2 (twice its lanes) and for AVX-512
// (four times). All give the same bits (tested). The caller picks: sweeptrace asks
// raytracer/accel/simd_path.hpp (the CPU's cpuid, and SWEEPTRACE_SIMD=scalar to force the
// baseline) and the CPU for AVX-512 (cli/denoise_image.cpp); the denoiser, a side stage, does not
// read the environment.
namespace sweeptrace::denoise {

enum class FilterIsa { Baseline, Avx2, Avx512 };

}  // namespace sweeptrace::denoise

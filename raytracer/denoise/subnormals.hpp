#pragma once
// The denoiser's arithmetic runs with subnormal floats and doubles flushed to zero (results: FTZ)
// and read as zero (operands: DAZ). NL-means and regression weights exp(-d) go down to 1e-38, so
// their products with features and colours land below the smallest normal float all the time,
// and on Intel cores every such multiply takes a microcode assist (measured on an Emerald Rapids
// Xeon: a `vmulps` with a subnormal result or operand 68-72 ns against 2 ns; the regression's
// tiles 22 % fewer samples flushed, docs/denoising.md). A weight below 1.2e-38 is no information
// the fit can use: the window's own centre weighs 1. The mode is a property of the thread (MXCSR),
// and TBB's worker threads do not take the caller's, so every parallel body of the denoiser
// (tiles.hpp) sets it on entry and puts the thread's own mode back on exit: the renderer and
// everything else keep IEEE subnormals. Every ISA's loops (baseline included: x86-64's scalar
// float arithmetic is SSE) follow the same MXCSR, so their bits stay each other's.
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace sweeptrace::denoise {

class SubnormalsFlushed {
public:
    SubnormalsFlushed();
    ~SubnormalsFlushed();
    SubnormalsFlushed(const SubnormalsFlushed&) = delete;
    SubnormalsFlushed& operator=(const SubnormalsFlushed&) = delete;

private:
    unsigned saved_ = 0;
};

#if defined(__SSE__) || defined(__x86_64__)
inline SubnormalsFlushed::SubnormalsFlushed() : saved_(_mm_getcsr()) {
    constexpr unsigned kFlushToZero = 1u << 15, kDenormalsAreZero = 1u << 6;
    _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero);
}
inline SubnormalsFlushed::~SubnormalsFlushed() { _mm_setcsr(saved_); }
#else
// Elsewhere the platform's own mode: the same image up to the subnormals' few bits.
inline SubnormalsFlushed::SubnormalsFlushed() = default;
inline SubnormalsFlushed::~SubnormalsFlushed() = default;
#endif

}  // namespace sweeptrace::denoise

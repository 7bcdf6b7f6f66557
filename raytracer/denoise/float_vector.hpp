#pragma once
// A vector of floats as wide as one register of the instruction set a loop is compiled for (GCC's
// vector extension): 4 lanes for the baseline (SSE2), 8 for AVX2, 16 for AVX-512; and of doubles,
// half as many. The register-blocked kernels (regression.cpp) keep their running sums in these,
// so the sums stay in registers across a window's pixels instead of being loaded and stored for
// every product. Each
// lane's + and * are the float operations of a scalar loop (the denoiser's files are built with
// -ffp-contract=off: no multiply-add is fused), so every width gives the same bits. Functions on
// these vectors are inlined into the loops of their own ISA (so the files that use them are built
// with -Wno-psabi: GCC's note that such a vector is passed differently across a call without AVX
// concerns calls that do not happen).
#include <cstddef>
#include <cstring>
#include <new>
#include <vector>

#include "raytracer/denoise/filter_isa.hpp"

namespace sweeptrace::denoise {

template <FilterIsa Isa>
struct FloatVectorOf;
template <>
struct FloatVectorOf<FilterIsa::Baseline> {
    typedef float type __attribute__((vector_size(16)));
};
template <>
struct FloatVectorOf<FilterIsa::Avx2> {
    typedef float type __attribute__((vector_size(32)));
};
template <>
struct FloatVectorOf<FilterIsa::Avx512> {
    typedef float type __attribute__((vector_size(64)));
};

template <FilterIsa Isa>
using FloatVector = typename FloatVectorOf<Isa>::type;

// The same register's worth of double lanes (the window solves, least_squares_lanes.hpp).
template <FilterIsa Isa>
struct DoubleVectorOf {
    typedef double type __attribute__((vector_size(sizeof(FloatVector<Isa>))));
};

template <FilterIsa Isa>
using DoubleVector = typename DoubleVectorOf<Isa>::type;

template <class V>
inline constexpr int kVectorLanes = int(sizeof(V) / sizeof(float));

// Loads and stores at any float address (the windows' slices are not aligned to a register).
template <class V>
[[gnu::always_inline]] inline V load_floats(const float* p) {
    V v;
    std::memcpy(&v, p, sizeof(V));
    return v;
}

template <class V>
[[gnu::always_inline]] inline void store_floats(float* p, const V& v) {
    std::memcpy(p, &v, sizeof(V));
}

template <class V>
[[gnu::always_inline]] inline V load_doubles(const double* p) {
    V v;
    std::memcpy(&v, p, sizeof(V));
    return v;
}

// Every lane `value` (a float or a double vector), from an array of lanes: written `value - V{}`,
// GCC -O3 built it, inlined into a loop, one lane at a time (16 masked broadcasts for one).
template <class V, class T>
[[gnu::always_inline]] inline V broadcast(T value) {
    T lanes[sizeof(V) / sizeof(T)];
    for (T& lane : lanes) lane = value;
    V v;
    std::memcpy(&v, lanes, sizeof(V));
    return v;
}

// An allocator of 64-byte aligned storage: a 512-bit load or store that crosses a cache line
// costs two of the line loads this CPU issues (Xeon Emerald Rapids: split loads of a zmm register
// at 2.6 G/s against 5.9 G/s aligned, measured), and a std::vector's malloc gives 16 bytes.
template <class T>
struct CacheLineAllocator {
    using value_type = T;
    static constexpr std::align_val_t kAlign{64};
    CacheLineAllocator() = default;
    template <class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) {}
    T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlign)); }
    void deallocate(T* p, std::size_t n) { ::operator delete(p, n * sizeof(T), kAlign); }
    template <class U>
    bool operator==(const CacheLineAllocator<U>&) const {
        return true;
    }
};

// Floats whose first element starts a cache line.
using AlignedFloats = std::vector<float, CacheLineAllocator<float>>;

}  // namespace sweeptrace::denoise

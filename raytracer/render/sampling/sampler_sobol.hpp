#pragma once
// The two-dimensional Sobol sequence and hash-based Owen scrambling (Burley 2020, "Practical
// Hash-based Owen Scrambling", JCGT 9(4)), the building blocks of the Sobol sampler (sampler.hpp).
//
// Points are 32-bit fixed-point fractions: x / 2^32 in [0, 1).
// - Dimension 0 is the van der Corput sequence (the index's bits reversed); dimension 1 is
//   Sobol's second dimension, from the primitive polynomial x + 1 with m_1 = 1, whose recurrence
//   m_k = 2 m_{k-1} xor m_{k-1} gives the direction integers (the Pascal matrix mod 2). Both are
//   derived here, not copied: together they are a (0, 2)-sequence in base 2, so every aligned
//   block of 2^k consecutive indices is a (0, k, 2)-net (each 2^-a x 2^-(k-a) box, a = 0..k,
//   holds exactly one point). The sampler pads every further dimension pair with an independently
//   shuffled copy of these two (Burley's padding), so no higher Sobol dimensions are needed.
// - owen_scramble is a nested uniform scramble: bit j of the result is bit j of the input flipped
//   by a function of the seed and the bits above j only. Such a permutation maps every elementary
//   box of [0, 1) onto another of the same size, so it keeps (0, k, 2)-nets nets, and for a random
//   seed each scrambled point is uniform on [0, 1) (the estimator stays unbiased). Burley's
//   Laine-Karras-style hash realises it: an addition and xors with products by even constants
//   change each bit of an integer only as a function of the bits below it, so applied to the
//   bit-reversed value it changes each digit only as a function of the digits above it.
// - The same scramble applied to a sample *index* shuffles the sequence's order: it maps each
//   aligned block of 2^k indices onto another aligned block (bit j depends on the bits above j),
//   so the first 2^k samples of a shuffled sequence still form a (0, k, 2)-net.
#include <array>
#include <cstdint>

namespace sweeptrace {

inline std::uint32_t reverse_bits32(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    return __builtin_bswap32(x);
}

// Direction integers of Sobol's dimension 1: V_k = m_k 2^(32-k), k = 1..32.
inline constexpr std::array<std::uint32_t, 32> kSobolDim1 = [] {
    std::array<std::uint32_t, 32> v{};
    std::uint32_t m = 1;  // m_1
    for (int k = 1; k <= 32; ++k) {
        v[static_cast<std::size_t>(k - 1)] = m << (32 - k);
        m = (m << 1) ^ m;  // m_{k+1}, kept mod 2^32 (only its low k+1 bits are ever used)
    }
    return v;
}();

inline std::uint32_t sobol_dim0(std::uint32_t index) { return reverse_bits32(index); }

// By the direction integers: the definition, kept as the reference the tests compare with.
inline std::uint32_t sobol_dim1_reference(std::uint32_t index) {
    std::uint32_t x = 0;
    for (std::size_t k = 0; index != 0; ++k, index >>= 1)
        if (index & 1u) x ^= kSobolDim1[k];
    return x;
}

// The same, branch-free. Bit t of m_k is C(k-1, t) mod 2 (m_k = (1 + x)^(k-1) over GF(2)), so
// fraction digit r (0 = the most significant) is the xor of the index bits j with C(j, r) odd,
// i.e. (Lucas) with r a bit-subset of j: a superset transform, five shift-xor steps.
// Returned bit-reversed (digit r at bit r), as owen_scramble works on it.
inline std::uint32_t sobol_dim1_reversed(std::uint32_t index) {
    std::uint32_t y = index;
    y ^= (y >> 1) & 0x55555555u;
    y ^= (y >> 2) & 0x33333333u;
    y ^= (y >> 4) & 0x0f0f0f0fu;
    y ^= (y >> 8) & 0x00ff00ffu;
    y ^= (y >> 16) & 0x0000ffffu;
    return y;
}
inline std::uint32_t sobol_dim1(std::uint32_t index) { return reverse_bits32(sobol_dim1_reversed(index)); }

// Burley 2020, listing 2 (his constants): a bijection whose bit j depends on bits <= j only.
inline std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

inline std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
    return reverse_bits32(laine_karras_permutation(reverse_bits32(x), seed));
}

// owen_scramble(sobol_dim0(index), seed) and owen_scramble(sobol_dim1(index), seed), without
// the bit reversals that cancel.
inline std::uint32_t scrambled_sobol_dim0(std::uint32_t index, std::uint32_t seed) {
    return reverse_bits32(laine_karras_permutation(index, seed));
}
inline std::uint32_t scrambled_sobol_dim1(std::uint32_t index, std::uint32_t seed) {
    return reverse_bits32(laine_karras_permutation(sobol_dim1_reversed(index), seed));
}

// Fixed point to float in [0, 1): the top 24 bits, so rounding can never produce 1.
inline float fraction_to_float(std::uint32_t x) { return static_cast<float>(x >> 8) * 0x1.0p-24f; }

}  // namespace sweeptrace

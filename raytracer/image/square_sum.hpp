#pragma once
// Exact sums of squares of fixed-point samples (partial_sum.hpp), so that a per-pixel variance
// is the same number whether one machine rendered the samples or farm parts did and were merged:
// integer addition is associative, a double sum of squares is not.
//
// A sample's fixed-point value x (|x| < 2^96) squared is below 2^192, and 2^31 of them below 2^223;
// the sum is kept as an unsigned 256-bit integer, four 64-bit limbs, least significant first.
// The variance of n samples with sum S and sum of squares Q is (n Q - S^2) / (n^2 (n - 1)),
// computed in 256-bit integers (n Q < 2^254, S^2 < 2^254, and n Q >= S^2 exactly by
// Cauchy-Schwarz), so identical samples give a variance of exactly 0, which a double
// Q/n - mean^2 does not. Only the exact difference n Q - S^2 is converted to double (limb by
// limb, the same roundings every time) and divided.
#include <cstdint>

#include "raytracer/image/partial_sum.hpp"

namespace sweeptrace {

struct SquareSum {
    std::uint64_t limb[4] = {0, 0, 0, 0};

    SquareSum& operator+=(const SquareSum& o) {
        unsigned carry = 0;
        for (int i = 0; i < 4; ++i) {
            const SumUInt s = static_cast<SumUInt>(limb[i]) + o.limb[i] + carry;
            limb[i] = static_cast<std::uint64_t>(s);
            carry = static_cast<unsigned>(s >> 64);
        }
        return *this;
    }
    bool operator==(const SquareSum&) const = default;
};

// The product of two unsigned 128-bit integers as a 256-bit one (schoolbook on 64-bit halves).
inline SquareSum wide_product(SumUInt a, SumUInt b) {
    const std::uint64_t a0 = static_cast<std::uint64_t>(a), a1 = static_cast<std::uint64_t>(a >> 64);
    const std::uint64_t b0 = static_cast<std::uint64_t>(b), b1 = static_cast<std::uint64_t>(b >> 64);
    SquareSum r;
    auto add_at = [&r](int at, SumUInt v) {  // v << (64 at), carried up
        SquareSum t;
        t.limb[at] = static_cast<std::uint64_t>(v);
        if (at + 1 < 4) t.limb[at + 1] = static_cast<std::uint64_t>(v >> 64);
        r += t;
    };
    add_at(0, static_cast<SumUInt>(a0) * b0);
    add_at(1, static_cast<SumUInt>(a0) * b1);
    add_at(1, static_cast<SumUInt>(a1) * b0);
    add_at(2, static_cast<SumUInt>(a1) * b1);
    return r;
}

// 2^(-2 bits), the unit of a square of fixed-point values with `bits` fraction bits (bits <= 63):
// exact, and a constant wherever `bits` is one (the callers').
constexpr double square_unit(int bits) { return 1.0 / static_cast<double>(static_cast<SumUInt>(1) << (2 * bits)); }

inline SumUInt magnitude(SumInt x) { return x < 0 ? static_cast<SumUInt>(0) - static_cast<SumUInt>(x) : static_cast<SumUInt>(x); }

// v, below 2^128, added to q: its carry into the upper limbs taken by a branch (rarely taken).
inline void add_narrow(SquareSum& q, SumUInt v) {
    const SumUInt lo = (static_cast<SumUInt>(q.limb[1]) << 64 | q.limb[0]) + v;
    const bool carry = lo < v;
    q.limb[0] = static_cast<std::uint64_t>(lo);
    q.limb[1] = static_cast<std::uint64_t>(lo >> 64);
    if (carry && ++q.limb[2] == 0) ++q.limb[3];
}

// m^2 added to q for a magnitude m < 2^64: one 64 x 64 -> 128-bit product. Nearly every sample's
// case: the feature sums call it for the values they know to be below 2^64, so it is inlined there
// rather than reached through add_square's test.
inline void add_small_square(SquareSum& q, std::uint64_t m) { add_narrow(q, static_cast<SumUInt>(m) * m); }

// x^2 added to q, x a fixed-point sample (to_fixed).
inline void add_square(SquareSum& q, SumInt x) {
    const SumUInt m = magnitude(x);
    if ((m >> 64) == 0) {  // |x| < 2^64 (a sample below 256)
        add_small_square(q, static_cast<std::uint64_t>(m));
        return;
    }
    q += wide_product(m, m);
}

// The variance of the mean of n samples whose fixed-point sum (2^-fraction_bits) is s and sum of
// squares q: the unbiased sample variance over n; 0 below 2 samples.
inline double variance_of_mean(SumInt s, const SquareSum& q, std::int64_t n, int fraction_bits = kSumFractionBits) {
    if (n < 2) return 0.0;
    const double nd = static_cast<double>(n);
    const double unit = square_unit(fraction_bits), over = nd * nd * (nd - 1.0);  // d unit exact, then / over
    const SumUInt m = magnitude(s);
    // Nearly every pixel (samples below 256, few enough of them): n q and s^2 fit 128 bits, and
    // their difference is converted to double once, rounded to nearest, as the general case
    // below converts any difference below 2^128, so the result depends on the sums only.
    if (q.limb[2] == 0 && q.limb[3] == 0 && (m >> 64) == 0) {
        SumUInt nq = 0;
        if (!__builtin_mul_overflow(static_cast<SumUInt>(q.limb[1]) << 64 | q.limb[0], static_cast<SumUInt>(n), &nq)) {
            const SumUInt s2 = m * m;
            return nq < s2 ? 0.0 : static_cast<double>(nq - s2) * unit / over;  // nq < s2: as `borrow` below
        }
    }
    // n q: 256 x 63 bits, exact because n q < 2^254.
    SquareSum nq;
    for (int i = 0; i < 4; ++i) {
        SquareSum t;
        const SumUInt p = static_cast<SumUInt>(q.limb[i]) * static_cast<std::uint64_t>(n);
        t.limb[i] = static_cast<std::uint64_t>(p);
        if (i + 1 < 4) t.limb[i + 1] = static_cast<std::uint64_t>(p >> 64);
        nq += t;
    }
    const SquareSum s2 = wide_product(m, m);
    // d = nq - s2 >= 0: two's complement subtraction, limb by limb.
    std::uint64_t borrow = 0;
    std::uint64_t diff[4];
    for (int i = 0; i < 4; ++i) {
        const SumUInt sub = static_cast<SumUInt>(s2.limb[i]) + borrow;
        diff[i] = nq.limb[i] - static_cast<std::uint64_t>(sub);
        borrow = static_cast<SumUInt>(nq.limb[i]) < sub ? 1 : 0;
    }
    if (borrow != 0) return 0.0;  // cannot happen for sums of the same samples; a damaged part reads as no variance
    if (diff[2] == 0 && diff[3] == 0) return static_cast<double>(static_cast<SumUInt>(diff[1]) << 64 | diff[0]) * unit / over;
    double d = 0.0;
    for (int i = 3; i >= 0; --i) d = d * 0x1p64 + static_cast<double>(diff[i]);
    return d * unit / over;
}

// The same for samples whose sum and sum of squares fit 64 and 128 bits (the bounded features,
// image/feature_sums.hpp: n < 2^31 samples of magnitude <= 2^32), so that n q < 2^126 and
// s^2 <= 2^126: n q - s^2 exact in 128 bits, converted to double once.
inline double variance_of_mean(std::int64_t s, SumUInt q, std::int64_t n, int fraction_bits) {
    if (n < 2) return 0.0;
    const SumUInt nq = q * static_cast<std::uint64_t>(n);
    const SumUInt m = static_cast<SumUInt>(s < 0 ? -static_cast<SumInt>(s) : static_cast<SumInt>(s));
    const SumUInt s2 = m * m;
    if (nq < s2) return 0.0;  // cannot happen for sums of the same samples; a damaged part reads as no variance
    const double nd = static_cast<double>(n);
    return static_cast<double>(nq - s2) * square_unit(fraction_bits) / (nd * nd * (nd - 1.0));
}

}  // namespace sweeptrace

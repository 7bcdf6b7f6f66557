#pragma once
// least_squares.hpp's solve for a vector of windows at once, one window per lane (a GCC vector of
// doubles, DoubleVector in float_vector.hpp): the same operations in the same order in every lane
// as solve_normal_equations, so the same bits (tested), several windows per instruction. The
// scalar solve runs one window's short dependent chains (a pivot search, a square root, a
// division, the next column) and was a tenth of NFOR's time. What differs per window (the pivot
// each step picks, where the factorisation stops) is taken per lane: the row and column swaps and
// the updates are selected by lane masks, and a swap is done only for a pivot some lane picked.
#include <cmath>
#include <cstddef>

#include "raytracer/denoise/float_vector.hpp"

namespace sweeptrace::denoise {

template <class M>
[[gnu::always_inline]] inline bool any_lane(const M& m) {
    for (std::size_t l = 0; l < sizeof(M) / sizeof(m[0]); ++l)
        if (m[l]) return true;
    return false;
}

// Lane by lane sqrt of d where `use`, 1 elsewhere (no square root of a negative is taken).
template <class VD, class M>
[[gnu::always_inline]] inline VD sqrt_lanes(const VD& d, const M& use) {
    VD r;
    for (std::size_t l = 0; l < sizeof(VD) / sizeof(double); ++l) r[l] = use[l] ? std::sqrt(d[l]) : 1.0;
    return r;
}

template <class VD>
[[gnu::always_inline]] inline void swap_where(decltype(VD{} < VD{}) sel, VD& x, VD& y) {
    const VD t = x;
    x = sel ? y : x;
    y = sel ? t : y;
}

// solve_normal_equations for each lane: A's lower triangle and diagonal in a[j][k], j >= k (the
// rest unused; overwritten), B in b (overwritten), beta written; n = N.
template <int N, class VD>
[[gnu::always_inline]] inline void solve_normal_equations_lanes(VD (&a)[N][N], VD (&b)[N][3], VD (&beta)[N][3], double precision) {
    using M = decltype(VD{} < VD{});
    const VD zero{};
    // Scaled to a unit diagonal; `scale` is carried through the pivots' swaps with `index`, the
    // original position of each row.
    VD scale[N], index[N];
    for (int i = 0; i < N; ++i) {
        const M positive = a[i][i] > zero;
        scale[i] = positive ? broadcast<VD>(1.0) / sqrt_lanes(a[i][i], positive) : zero;
        index[i] = broadcast<VD>(double(i));
    }
    for (int i = 0; i < N; ++i) {
        for (int j = 0; j <= i; ++j) a[i][j] *= scale[i] * scale[j];
        for (int c = 0; c < 3; ++c) b[i][c] *= scale[i];
    }
    const VD tolerance = broadcast<VD>(N * precision);
    M active = zero == zero;  // not stopped yet
    VD rank = zero;
    for (int k = 0; k < N; ++k) {
        VD best = a[k][k], pick = broadcast<VD>(double(k));
        for (int j = k + 1; j < N; ++j) {
            const M larger = a[j][j] > best;
            best = larger ? a[j][j] : best;
            pick = larger ? broadcast<VD>(double(j)) : pick;
        }
        active &= best > tolerance;
        if (!any_lane(active)) break;
        // Rows and columns k and m swapped in the lanes that picked m (the lower triangle's
        // view of swapping both in the symmetric matrix, as LAPACK's dpstrf does).
        for (int m = k + 1; m < N; ++m) {
            const M sel = active & (pick == broadcast<VD>(double(m)));
            if (!any_lane(sel)) continue;
            for (int j = 0; j < k; ++j) swap_where(sel, a[k][j], a[m][j]);
            swap_where(sel, a[k][k], a[m][m]);
            for (int j = k + 1; j < m; ++j) swap_where(sel, a[j][k], a[m][j]);
            for (int j = m + 1; j < N; ++j) swap_where(sel, a[j][k], a[j][m]);
            for (int c = 0; c < 3; ++c) swap_where(sel, b[k][c], b[m][c]);
            swap_where(sel, index[k], index[m]);
            swap_where(sel, scale[k], scale[m]);
        }
        const VD pivot = sqrt_lanes(a[k][k], active);
        a[k][k] = active ? pivot : a[k][k];
        for (int i = k + 1; i < N; ++i) a[i][k] = active ? a[i][k] / pivot : a[i][k];
        for (int i = k + 1; i < N; ++i)
            for (int j = k + 1; j <= i; ++j) a[i][j] = active ? a[i][j] - a[i][k] * a[j][k] : a[i][j];
        rank = active ? rank + broadcast<VD>(1.0) : rank;
    }
    // L L^T z = b on each lane's first `rank` rows; the rest of z is 0.
    for (int t = 0; t < N; ++t)
        for (int c = 0; c < 3; ++c) beta[t][c] = zero;
    for (int c = 0; c < 3; ++c) {
        VD z[N];
        for (int i = 0; i < N; ++i) {
            VD s = b[i][c];
            for (int j = 0; j < i; ++j) s -= a[i][j] * z[j];
            z[i] = broadcast<VD>(double(i)) < rank ? s / a[i][i] : zero;
        }
        for (int i = N - 1; i >= 0; --i) {
            VD s = z[i];
            for (int j = i + 1; j < N; ++j) s = broadcast<VD>(double(j)) < rank ? s - a[j][i] * z[j] : s;
            z[i] = broadcast<VD>(double(i)) < rank ? s / a[i][i] : zero;
        }
        // beta at each row's original position
        for (int i = 0; i < N; ++i) {
            const VD value = z[i] * scale[i];
            for (int t = 0; t < N; ++t) beta[t][c] = index[i] == broadcast<VD>(double(t)) ? value : beta[t][c];
        }
    }
}

}  // namespace sweeptrace::denoise

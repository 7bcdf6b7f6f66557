// Pivoted Cholesky on the scaled normal equations (least_squares.hpp).
#include "raytracer/denoise/least_squares.hpp"

#include <cmath>
#include <utility>

namespace sweeptrace::denoise {

void solve_normal_equations(double* a, double* b, int n, double* beta, double precision) {
    double scale[kMaxRegressionTerms];
    int perm[kMaxRegressionTerms];
    for (int i = 0; i < n; ++i) {
        scale[i] = a[i * n + i] > 0.0 ? 1.0 / std::sqrt(a[i * n + i]) : 0.0;
        perm[i] = i;
    }
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) a[i * n + j] *= scale[i] * scale[j];
        for (int c = 0; c < 3; ++c) b[i * 3 + c] *= scale[i];
    }
    const double tolerance = n * precision;  // relative to the unit diagonal
    int rank = 0;
    for (int k = 0; k < n; ++k) {
        int best = k;
        for (int j = k + 1; j < n; ++j)
            if (a[j * n + j] > a[best * n + best]) best = j;
        if (!(a[best * n + best] > tolerance)) break;
        if (best != k) {
            for (int j = 0; j < n; ++j) std::swap(a[k * n + j], a[best * n + j]);
            for (int j = 0; j < n; ++j) std::swap(a[j * n + k], a[j * n + best]);
            for (int c = 0; c < 3; ++c) std::swap(b[k * 3 + c], b[best * 3 + c]);
            std::swap(perm[k], perm[best]);
        }
        const double pivot = std::sqrt(a[k * n + k]);
        a[k * n + k] = pivot;
        for (int i = k + 1; i < n; ++i) a[i * n + k] /= pivot;
        // The trailing block loses the outer product of column k (lower triangle and diagonal,
        // mirrored so the pivot search and swaps above see a symmetric matrix).
        for (int i = k + 1; i < n; ++i)
            for (int j = k + 1; j <= i; ++j) {
                a[i * n + j] -= a[i * n + k] * a[j * n + k];
                a[j * n + i] = a[i * n + j];
            }
        ++rank;
    }
    // L L^T z = b on the first `rank` rows; the rest of z is 0.
    double z[kMaxRegressionTerms * 3] = {};
    for (int c = 0; c < 3; ++c) {
        for (int i = 0; i < rank; ++i) {
            double s = b[i * 3 + c];
            for (int j = 0; j < i; ++j) s -= a[i * n + j] * z[j * 3 + c];
            z[i * 3 + c] = s / a[i * n + i];
        }
        for (int i = rank - 1; i >= 0; --i) {
            double s = z[i * 3 + c];
            for (int j = i + 1; j < rank; ++j) s -= a[j * n + i] * z[j * 3 + c];
            z[i * 3 + c] = s / a[i * n + i];
        }
    }
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) beta[perm[i] * 3 + c] = z[i * 3 + c] * scale[perm[i]];
}

}  // namespace sweeptrace::denoise

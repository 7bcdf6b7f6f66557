#pragma once
// The weighted least-squares solve of one regression window (regression.hpp), from its normal
// equations: small (the features plus three), symmetric and often singular, since a window on one
// flat wall has constant normals and albedo.
namespace sweeptrace::denoise {

inline constexpr int kMaxRegressionTerms = 16;

// Solves A beta = B for beta (n x 3, row-major), A (n x n, row-major, symmetric positive
// semi-definite; overwritten) and B (n x 3; overwritten), n <= kMaxRegressionTerms. Columns are
// first scaled to a unit diagonal (features of any unit), then a Cholesky factorisation with
// diagonal pivoting stops at the first pivot below n * `precision` (LAPACK dpstrf's default
// tolerance, n x the relative precision of A's entries: double's epsilon for sums taken in double,
// more for sums taken in float): the directions the data does not determine get coefficient 0,
// which gives the prediction the determined directions allow. A column whose diagonal is 0 (a
// feature constant over the window) is one of them.
void solve_normal_equations(double* a, double* b, int n, double* beta, double precision);

}  // namespace sweeptrace::denoise

#pragma once
// Monte Carlo estimates with their standard errors, so tests compare estimates against truth (or
// each other) in units of the estimated noise instead of by a guessed tolerance.
#include <cmath>
#include <cstdint>

namespace sweeptrace::test {

// Running mean and variance (Welford), in double.
struct Estimate {
    std::uint64_t n = 0;
    double mean = 0.0, m2 = 0.0;

    void add(double x) {
        ++n;
        const double d = x - mean;
        mean += d / static_cast<double>(n);
        m2 += d * (x - mean);
    }
    double variance_of_mean() const { return n > 1 ? m2 / static_cast<double>(n - 1) / static_cast<double>(n) : 0.0; }
    double standard_error() const { return std::sqrt(variance_of_mean()); }
};

// Bound on |z| for one of `tests` simultaneous two-sided z-tests, such that all of them pass by
// chance with probability >= 1 - 1e-6 (Bonferroni: per test alpha = 1e-6 / tests; the normal
// tail bound P(|Z| > z) <= 2 phi(z) / z gives the z below, rounded up). Tests with up to ~1000
// comparisons use 6.2; fewer use the smaller bounds.
inline double z_bound(int tests) {
    if (tests <= 1) return 5.0;    // alpha 1e-6:   P(|Z| > 5.0) = 5.7e-7
    if (tests <= 10) return 5.5;   // alpha 1e-7:   P(|Z| > 5.5) = 3.8e-8
    if (tests <= 100) return 5.9;  // alpha 1e-8:   P(|Z| > 5.9) = 3.6e-9
    return 6.2;                    // alpha 1e-9:   P(|Z| > 6.2) = 5.6e-10 (up to 1000 tests)
}

}  // namespace sweeptrace::test

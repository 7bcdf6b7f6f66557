#pragma once
// The check every swept test is held to: a fine search with the discrete test must agree with
// the returned time of impact.
//
// `overlaps(t)` runs the discrete test with the moving shape at start + t * motion (positions
// rounded to float, as any caller would have them). The search samples [0, 1] at 64 even steps
// plus t - delta and t + delta, takes the first sample that overlaps, and bisects (40 halvings)
// between it and the last non-overlapping sample before it, giving the discrete first contact
// time t_d. Required:
//  - swept miss  -> no sample overlaps;
//  - swept hit t -> the discrete test overlaps in [t, min(t + delta, 1)] and t_d >= t - delta:
//    "is there any contact in [0, t - delta]?" is answered no. (Every pair here is convex, so
//    the contact times form one interval and t_d is its start.)
// delta, the tolerance, is derived in time_tolerance() below.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include <catch2/catch.hpp>

#include "collision/hit.hpp"
#include "collision/overlap.hpp"
#include "collision/swept.hpp"
#include "random_cases.hpp"

namespace testing {

// Tolerance on t. Positions handed to the discrete test are rounded to float (0.5 ulp each of
// the moving and still coordinates, <= 2^-24 M together for coordinates of magnitude <= M), and
// the swept routines state t errors of at most ~32 roundings relative to the same scale over
// the approach speed (intersect_sphere.cpp: gamma(32) (|f| + r)(1 + r/h) / |d|; r/h is
// |motion| / |motion . n| at the entry point). A gap error e in distance becomes e / |motion . n|
// in time, n the contact normal: the distance between the shapes changes at that rate. So
//   delta = 64 * 2^-24 * M / |motion . n| + 64 * 2^-24,
// the second term covering the rounding of t itself. Grazing contacts (motion . n -> 0) are
// ill-conditioned for any method and get a correspondingly wide window.
inline double time_tolerance(double scale, const glm::vec3& motion, const glm::vec3& normal) {
    const double eps = std::ldexp(1.0, -24);
    const double rate = std::abs(double(glm::dot(motion, normal)));
    return 64.0 * eps * scale / std::max(rate, 1e-30) + 64.0 * eps;
}

struct SweptCheckStats {
    int hits = 0, misses = 0, at_start = 0;
};

template <class Overlaps>
void check_against_discrete(const collision::TimeOfImpact& toi, double scale, const glm::vec3& motion,
                            Overlaps overlaps, SweptCheckStats& stats) {
    std::vector<double> ts;
    for (int i = 0; i <= 64; ++i) ts.push_back(i / 64.0);
    double delta = 0.0;
    if (toi.hit) {
        REQUIRE(toi.t >= 0.0f);
        REQUIRE(toi.t <= 1.0f);
        REQUIRE(std::abs(glm::length(toi.normal) - 1.0f) < 1e-5f);
        REQUIRE(std::isfinite(toi.point.x));
        REQUIRE(std::isfinite(toi.point.y));
        REQUIRE(std::isfinite(toi.point.z));
        delta = time_tolerance(scale, motion, toi.normal);
        if (toi.t - delta > 0.0) ts.push_back(toi.t - delta);
        ts.push_back(std::min(1.0, toi.t + delta));
        std::sort(ts.begin(), ts.end());
    }
    std::size_t first = ts.size();
    for (std::size_t i = 0; i < ts.size(); ++i)
        if (overlaps(ts[i])) {
            first = i;
            break;
        }
    if (!toi.hit) {
        INFO("swept: miss; discrete overlaps at t = " << (first < ts.size() ? ts[first] : -1.0));
        REQUIRE(first == ts.size());
        ++stats.misses;
        return;
    }
    INFO("swept t = " << toi.t << ", delta = " << delta);
    // Contact just after t: the discrete test must overlap somewhere in [t, min(t + delta, 1)]
    // (16 samples; a grazing contact can be shorter than a wide delta window, so one sample at
    // t + delta is not enough). At t = 0 it must overlap at once.
    bool after = overlaps(toi.t);
    for (int k = 1; k <= 16 && !after && toi.t > 0.0f; ++k) after = overlaps(std::min(1.0, toi.t + delta * k / 16.0));
    REQUIRE(after);
    REQUIRE(first < ts.size());
    double td = ts[first];
    if (first > 0) {
        double lo = ts[first - 1], hi = ts[first];
        for (int k = 0; k < 40; ++k) {
            const double mid = 0.5 * (lo + hi);
            (overlaps(mid) ? hi : lo) = mid;
        }
        td = hi;
    }
    INFO("discrete first contact t_d = " << td);
    REQUIRE(td >= toi.t - delta);
    REQUIRE(td <= toi.t + delta);
    if (toi.t == 0.0f) ++stats.at_start;
    else ++stats.hits;
}

template <class Shape>
Shape moved_by(Shape s, const glm::vec3& d) {
    s.center += d;
    return s;
}
inline collision::Triangle moved_by(const collision::Triangle& t, const glm::vec3& d) {
    return {t.a + d, t.b + d, t.c + d};
}
inline bool hit_of(const collision::Contact& c) { return c.hit; }
inline bool hit_of(bool b) { return b; }

// `count` seeded cases from make(rng) -> {moving, motion, still}, each swept and checked with
// check_against_discrete(); `scale` must bound every coordinate and size involved.
template <class Make>
SweptCheckStats random_sweeps(std::uint32_t seed, int count, double scale, Make make) {
    SeededRng rng(seed);
    SweptCheckStats stats;
    for (int i = 0; i < count; ++i) {
        const auto [moving, motion, still] = make(rng);
        const collision::TimeOfImpact r = collision::sweep(moving, motion, still);
        INFO("case " << i);
        check_against_discrete(r, scale, motion, [&, &m = moving, &v = motion, &s = still](double t) {
            return hit_of(collision::overlap(moved_by(m, glm::vec3(glm::dvec3(v) * t)), s));
        }, stats);
    }
    return stats;
}

}  // namespace testing

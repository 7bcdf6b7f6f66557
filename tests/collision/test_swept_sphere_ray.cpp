// sweep_interval (collision/swept_sphere_ray.cpp): the times a moving sphere spends on a line,
// against a long-double reference, with the bound the file states, and its degenerate cases.
#include <catch2/catch.hpp>

#include <cmath>

#include "collision/swept.hpp"
#include "random_cases.hpp"

namespace {

struct Reference {
    bool hit = false;
    long double t0 = 0, t1 = 0, margin = 0;  // margin: sqrt(disc) / M, how far from tangency
};

// The same quadratic in long double, solved by the textbook formula (accurate enough here: the
// cases are kept away from tangency and from a = 0).
Reference reference(const collision::Sphere& s, const glm::vec3& v, const collision::Ray& line) {
    using L = long double;
    const L dx = line.dir.x, dy = line.dir.y, dz = line.dir.z;
    const L n = std::sqrt(dx * dx + dy * dy + dz * dz);
    const L u[3] = {dx / n, dy / n, dz / n};
    const L w[3] = {L(s.center.x) - line.origin.x, L(s.center.y) - line.origin.y, L(s.center.z) - line.origin.z};
    const L m[3] = {v.x, v.y, v.z};
    const L wu = w[0] * u[0] + w[1] * u[1] + w[2] * u[2], mu = m[0] * u[0] + m[1] * u[1] + m[2] * u[2];
    L wp[3], mp[3];
    for (int i = 0; i < 3; ++i) {
        wp[i] = w[i] - wu * u[i];
        mp[i] = m[i] - mu * u[i];
    }
    const L a = mp[0] * mp[0] + mp[1] * mp[1] + mp[2] * mp[2];
    const L b = -(wp[0] * mp[0] + wp[1] * mp[1] + wp[2] * mp[2]);
    const L ww = wp[0] * wp[0] + wp[1] * wp[1] + wp[2] * wp[2];
    const L c = ww - L(s.radius) * s.radius;
    Reference r;
    const L disc = b * b - a * c;
    r.margin = std::sqrt(std::fabs(disc)) / (a + 2 * std::fabs(b) + ww + L(s.radius) * s.radius);
    if (disc < 0) return r;
    const L lo = (b - std::sqrt(disc)) / a, hi = (b + std::sqrt(disc)) / a;
    if (hi < 0 || lo > 1) return r;
    r.hit = true;
    r.t0 = lo < 0 ? 0 : lo;
    r.t1 = hi > 1 ? 1 : hi;
    return r;
}

}  // namespace

TEST_CASE("sweep_interval: each end within 2 float ulps of a long-double reference", "[swept][motion]") {
    testing::SeededRng rng(2512);
    int hits = 0, checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const collision::Sphere s{rng.vec(-2.0f, 2.0f), rng.uniform(0.1f, 1.5f)};
        const glm::vec3 v = rng.vec(-3.0f, 3.0f);
        const collision::Ray line{rng.vec(-4.0f, 4.0f), rng.vec(-1.0f, 1.0f)};
        const Reference ref = reference(s, v, line);
        if (ref.margin < 1e-6L) continue;  // near tangency: the bound does not apply
        ++checked;
        const collision::TimeInterval got = collision::sweep_interval(s, v, line);
        REQUIRE(got.hit == ref.hit);
        if (!got.hit) continue;
        ++hits;
        const float ulp0 = std::nextafter(float(ref.t0), 2.0f) - float(ref.t0);
        const float ulp1 = std::nextafter(float(ref.t1), 2.0f) - float(ref.t1);
        CHECK(std::fabs(got.t0 - ref.t0) <= 2.0L * ulp0);
        CHECK(std::fabs(got.t1 - ref.t1) <= 2.0L * ulp1);
    }
    CHECK(checked > 15000);
    CHECK(hits > 1500);  // the cases exercise both answers
}

TEST_CASE("sweep_interval: degenerate motion and input", "[swept][motion]") {
    const collision::Ray line{{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}};
    // Motion along the line: the sphere is on it all step long, or never.
    auto along = collision::sweep_interval({{0.0f, 0.5f, 0.0f}, 1.0f}, {0.0f, 0.0f, 3.0f}, line);
    CHECK(along.hit);
    CHECK(along.t0 == 0.0f);
    CHECK(along.t1 == 1.0f);
    CHECK_FALSE(collision::sweep_interval({{0.0f, 2.0f, 0.0f}, 1.0f}, {0.0f, 0.0f, 3.0f}, line).hit);
    // Across: centre from x = -2 to x = 2, radius 1: on the line while |x| <= 1, t in [1/4, 3/4].
    auto across = collision::sweep_interval({{-2.0f, 0.0f, 0.0f}, 1.0f}, {4.0f, 0.0f, 0.0f}, line);
    CHECK(across.hit);
    CHECK(across.t0 == 0.25f);
    CHECK(across.t1 == 0.75f);
    CHECK_FALSE(collision::sweep_interval({{0.0f, 0.0f, 0.0f}, 0.0f}, {1.0f, 0.0f, 0.0f}, line).hit);
    CHECK_FALSE(collision::sweep_interval({{0.0f, 0.0f, 0.0f}, 1.0f}, {1.0f, 0.0f, 0.0f}, {{0, 0, 5}, {0, 0, 0}}).hit);
    CHECK_FALSE(collision::sweep_interval({{0.0f, 0.0f, 0.0f}, 1.0f}, {NAN, 0.0f, 0.0f}, line).hit);
}

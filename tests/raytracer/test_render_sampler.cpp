// The Sobol sampler (render/sampling/sampler.hpp, sampler_sobol.hpp): the nets it promises, exactly; its
// discrepancy against random points; addressing by (seed, pixel, sample, dimension) so any order
// or split of the work gives the same numbers; the independent sampler being today's stream.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/roulette.hpp"
#include "raytracer/render/sampling/sampler.hpp"

using namespace sweeptrace;

namespace {

using Point = glm::dvec2;

// Every elementary box 2^-a x 2^-(k-a), a = 0..k, holds exactly one of the 2^k points.
bool is_0mk2_net(const std::vector<Point>& pts, int k) {
    const std::size_t n = std::size_t(1) << k;
    if (pts.size() != n) return false;
    for (int a = 0; a <= k; ++a) {
        std::vector<int> count(n, 0);
        for (const Point& p : pts) {
            const auto bx = static_cast<std::size_t>(std::floor(p.x * double(1u << a)));
            const auto by = static_cast<std::size_t>(std::floor(p.y * double(1u << (k - a))));
            if (bx >= (1u << a) || by >= (1u << (k - a))) return false;
            if (++count[(bx << (k - a)) | by] != 1) return false;
        }
    }
    return true;
}

// One point in each interval [j 2^-k, (j+1) 2^-k).
bool is_stratified_1d(const std::vector<double>& u, int k) {
    const std::size_t n = std::size_t(1) << k;
    std::vector<int> count(n, 0);
    for (double v : u) {
        const auto j = static_cast<std::size_t>(std::floor(v * double(n)));
        if (j >= n || ++count[j] != 1) return false;
    }
    return u.size() == n;
}

double fixed(std::uint32_t x) { return double(x) * 0x1.0p-32; }

// Exact star discrepancy of a 2D point set: the sup over anchored boxes [0, x) x [0, y) of
// |count / N - x y| is reached with x and y at point coordinates (or 1), for closed or open boxes.
double star_discrepancy(const std::vector<Point>& pts) {
    std::vector<double> xs{1.0}, ys{1.0};
    for (const Point& p : pts) {
        xs.push_back(p.x);
        ys.push_back(p.y);
    }
    const double n = double(pts.size());
    double d = 0.0;
    for (double x : xs) {
        for (double y : ys) {
            int open = 0, closed = 0;
            for (const Point& p : pts) {
                open += p.x < x && p.y < y;
                closed += p.x <= x && p.y <= y;
            }
            d = std::max({d, x * y - open / n, closed / n - x * y});
        }
    }
    return d;
}

std::vector<Point> sampler_points(SamplerKind kind, std::uint64_t seed, std::uint64_t pixel, int dim, int n) {
    std::vector<Point> pts;
    for (int i = 0; i < n; ++i) {
        PixelSampler s(kind, seed, pixel, std::uint64_t(i));
        const glm::vec2 u = s.get2d(dim);
        pts.push_back({u.x, u.y});
    }
    return pts;
}

// Every 2D slot of the camera and of the first bounces, and every 1D slot (each coordinate of a 2D
// slot is stratified in 1D as the net's 2^-k x 1 boxes say).
std::vector<int> slots_2d() {
    std::vector<int> d{sample_dim::kFilm, sample_dim::kLens};
    for (int b = 0; b < 4; ++b) {
        d.push_back(sample_dim::bounce(b, sample_dim::kLightChoice));  // with kLightPart
        d.push_back(sample_dim::bounce(b, sample_dim::kLightPoint));
        d.push_back(sample_dim::bounce(b, sample_dim::kBsdfDirection));
    }
    return d;
}
std::vector<int> slots_1d() {
    std::vector<int> d;
    for (int b = 0; b < 4; ++b)
        for (int slot : {sample_dim::kBsdfLobe, sample_dim::kRoulette})
            d.push_back(sample_dim::bounce(b, slot));
    return d;
}

}  // namespace

TEST_CASE("sobol: the direction integers and the branch-free dimension 1 are Sobol's", "[render][sampler]") {
    // m_k of x + 1: 1, 3, 5, 15, 17, 51 (Joe and Kuo's table starts dimension 2 with m_1 = 1).
    const std::uint32_t m[] = {1, 3, 5, 15, 17, 51};
    for (int k = 1; k <= 6; ++k) CHECK(kSobolDim1[std::size_t(k - 1)] == m[k - 1] << (32 - k));
    // The first points of dimension 1 in natural (not Gray-code) order: x_i = xor of V_k over i's bits.
    const double first[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    for (std::uint32_t i = 0; i < 8; ++i) CHECK(fixed(sobol_dim1(i)) == first[i]);
    Rng rng(7, 0, 0);
    for (int i = 0; i < 100000; ++i) {
        const std::uint32_t index = i < 50000 ? std::uint32_t(i) : rng.next_u32();
        REQUIRE(sobol_dim1(index) == sobol_dim1_reference(index));
        const std::uint32_t seed = rng.next_u32();
        REQUIRE(scrambled_sobol_dim0(index, seed) == owen_scramble(sobol_dim0(index), seed));
        REQUIRE(scrambled_sobol_dim1(index, seed) == owen_scramble(sobol_dim1(index), seed));
    }
}

TEST_CASE("sobol: aligned blocks of 2^k points are (0, k, 2)-nets, unscrambled and scrambled", "[render][sampler]") {
    for (int k = 0; k <= 12; ++k) {
        for (std::uint32_t block : {0u, 1u, 977u}) {
            for (std::uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
                std::vector<Point> plain, scrambled;
                for (std::uint32_t j = 0; j < (1u << k); ++j) {
                    const std::uint32_t i = (block << k) | j;
                    plain.push_back({fixed(sobol_dim0(i)), fixed(sobol_dim1(i))});
                    scrambled.push_back({fixed(owen_scramble(sobol_dim0(i), seed)),
                                         fixed(owen_scramble(sobol_dim1(i), seed * 3u + 1u))});
                }
                INFO("k " << k << ", block " << block << ", seed " << seed);
                REQUIRE(is_0mk2_net(plain, k));
                REQUIRE(is_0mk2_net(scrambled, k));
            }
        }
    }
    // A failing control: the scrambled points of two different blocks together are no net.
    std::vector<Point> mixed;
    for (std::uint32_t j = 0; j < 8; ++j) mixed.push_back({fixed(sobol_dim0(j)), fixed(sobol_dim1(j))});
    for (std::uint32_t j = 16; j < 24; ++j) mixed.push_back({fixed(sobol_dim0(j)), fixed(sobol_dim1(j))});
    mixed.resize(16);
    std::swap(mixed[0], mixed[15]);
    mixed[15] = mixed[14];  // a repeated point: two in one box
    CHECK_FALSE(is_0mk2_net(mixed, 4));
}

TEST_CASE("sampler: the first 2^k samples of every 2D slot of a pixel are a (0, k, 2)-net, every 1D slot stratified",
          "[render][sampler]") {
    for (int k : {2, 5, 8, 10}) {
        for (std::uint64_t pixel : {0ull, 12345ull}) {
            for (int dim : slots_2d()) {
                INFO("k " << k << ", pixel " << pixel << ", dim " << dim);
                REQUIRE(is_0mk2_net(sampler_points(SamplerKind::Sobol, 3, pixel, dim, 1 << k), k));
            }
            for (int dim : slots_1d()) {
                std::vector<double> u;
                for (int i = 0; i < (1 << k); ++i) u.push_back(PixelSampler(SamplerKind::Sobol, 3, pixel, i).get1d(dim));
                INFO("k " << k << ", pixel " << pixel << ", 1D dim " << dim);
                REQUIRE(is_stratified_1d(u, k));
            }
        }
    }
    // The independent sampler's points are no net (a control that the check can fail).
    CHECK_FALSE(is_0mk2_net(sampler_points(SamplerKind::Independent, 3, 0, 0, 256), 8));
}

TEST_CASE("sampler: star discrepancy of 256 Sobol points is far below random points'", "[render][sampler]") {
    // Random points: E[D*] ~ 1/sqrt(N) (about 0.06 at N = 256); a (0, m, 2)-net in base 2 has
    // N D* <= m/2 + 3/2 (Niederreiter 1992, Theorem 4.5 with b = 2, s = 2, t = 0): 5.5/256 =
    // 0.021 here, a factor ~3 below random. Both are measured, over several pixels and slots.
    const int n = 256, m = 8;
    double random_sum = 0.0;
    const int sets = 12;
    for (int s = 0; s < sets; ++s) random_sum += star_discrepancy(sampler_points(SamplerKind::Independent, 5, s, 0, n));
    const double random_mean = random_sum / sets;
    INFO("random points: mean D* " << random_mean);
    CHECK(random_mean > 0.04);
    double sobol_max = 0.0;
    for (std::uint64_t pixel = 0; pixel < 3; ++pixel)
        for (int dim : {sample_dim::kFilm, sample_dim::bounce(0, sample_dim::kLightPoint),
                        sample_dim::bounce(2, sample_dim::kBsdfDirection)})
            sobol_max = std::max(sobol_max, star_discrepancy(sampler_points(SamplerKind::Sobol, 5, pixel, dim, n)));
    INFO("sobol points: max D* " << sobol_max);
    CHECK(sobol_max * n <= m / 2.0 + 1.5);
    CHECK(sobol_max < random_mean / 2.5);
}

TEST_CASE("sampler: values depend only on (seed, pixel, sample, dimension), not on the order asked", "[render][sampler]") {
    const int dims[] = {sample_dim::kFilm, sample_dim::kLens, sample_dim::bounce(0, sample_dim::kBsdfLobe),
                        sample_dim::bounce(3, sample_dim::kBsdfDirection),
                        sample_dim::bounce(sample_dim::kSobolBounces, sample_dim::kLightPoint),  // hashed
                        sample_dim::bounce(sample_dim::kSobolBounces + 5, sample_dim::kRoulette)};
    for (std::uint64_t sample : {0ull, 1ull, 1000ull}) {
        PixelSampler forward(SamplerKind::Sobol, 9, 77, sample), backward(SamplerKind::Sobol, 9, 77, sample);
        std::vector<glm::vec2> a, b;
        for (int d : dims) a.push_back(forward.get2d(d));
        for (auto it = std::rbegin(dims); it != std::rend(dims); ++it) b.push_back(backward.get2d(*it));
        std::reverse(b.begin(), b.end());
        CHECK(a == b);
        CHECK(PixelSampler(SamplerKind::Sobol, 9, 77, sample).get1d(dims[2]) ==
              PixelSampler(SamplerKind::Sobol, 9, 77, sample).get1d(dims[2]));
    }
    // Different pixels, seeds and dimensions give different numbers.
    const auto at = [](std::uint64_t seed, std::uint64_t pixel, int dim) {
        return PixelSampler(SamplerKind::Sobol, seed, pixel, 3).get2d(dim);
    };
    CHECK(at(1, 2, 0) != at(1, 3, 0));
    CHECK(at(1, 2, 0) != at(2, 2, 0));
    CHECK(at(1, 2, 0) != at(1, 2, sample_dim::kLens));
}

TEST_CASE("sampler: hashed dimensions past the stratified bounces are uniform", "[render][sampler]") {
    const int dim = sample_dim::bounce(sample_dim::kSobolBounces, sample_dim::kBsdfDirection);
    const int n = 40000;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < n; ++i) {
        const glm::vec2 u = PixelSampler(SamplerKind::Sobol, 1, std::uint64_t(i % 97), std::uint64_t(i)).get2d(dim);
        REQUIRE(u.x >= 0.0f);
        REQUIRE(u.x < 1.0f);
        REQUIRE(u.y >= 0.0f);
        REQUIRE(u.y < 1.0f);
        sx += u.x, sy += u.y, sxx += double(u.x) * u.x, sxy += double(u.x) * u.y;
    }
    // Means 1/2 and E[x^2] = 1/3 within 5 sigma (sigma of a mean of n uniforms: 0.2887 / sqrt n);
    // E[xy] = 1/4 (independent coordinates).
    const double tol = 5.0 * 0.2887 / std::sqrt(double(n));
    CHECK(std::abs(sx / n - 0.5) < tol);
    CHECK(std::abs(sy / n - 0.5) < tol);
    CHECK(std::abs(sxx / n - 1.0 / 3.0) < tol);
    CHECK(std::abs(sxy / n - 0.25) < tol);
}

TEST_CASE("sampler: independent is the per-sample PCG stream in call order", "[render][sampler]") {
    PixelSampler s(SamplerKind::Independent, 11, 5, 6);
    Rng rng(11, 5, 6);
    const glm::vec2 a = s.get2d(sample_dim::kFilm);
    CHECK(a.x == rng.uniform());
    CHECK(a.y == rng.uniform());
    CHECK(s.get1d(sample_dim::bounce(0, sample_dim::kBsdfLobe)) == rng.uniform());
    CHECK(s.get1d(12345) == rng.uniform());  // dimensions are ignored
}

TEST_CASE("roulette: the stated policies", "[render][roulette]") {
    const RoulettePolicy classic = RoulettePolicy::classic();
    CHECK(survival_probability(classic, 2, 0.01f) == 1.0f);  // before the start vertex
    CHECK(survival_probability(classic, 3, 0.25f) == 0.25f);
    CHECK(survival_probability(classic, 3, 1.5f) == 1.0f);
    const RoulettePolicy half{4, 0.5f, true};
    CHECK(survival_probability(half, 3, 0.01f) == 1.0f);
    CHECK(survival_probability(half, 4, 0.5f) == 1.0f);   // at the threshold: not below it
    CHECK(survival_probability(half, 4, 0.25f) == 0.5f);  // survivors carry the threshold again
    CHECK(survival_probability(half, 9, 0.0f) == 0.0f);   // a path that carries nothing stops
}

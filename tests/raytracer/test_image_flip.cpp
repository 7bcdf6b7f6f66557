// FLIP checked against the paper's stated properties and values derived by hand from its
// formulas (docs/flip.md), not against numbers printed by this implementation.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "raytracer/image/flip.hpp"
#include "raytracer/image/flip_color.hpp"
#include "raytracer/input_error.hpp"

using namespace sweeptrace;

namespace {

Image flat(int w, int h, glm::vec3 v) {
    Image image(w, h);
    for (auto& p : image.pixels) p = v;
    return image;
}

Image noise(int w, int h, unsigned seed, float scale = 1.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, scale);
    Image image(w, h);
    for (auto& p : image.pixels) p = {u(rng), u(rng), u(rng)};
    return image;
}

// The colour term by hand from CIELAB values of the sRGB primaries as tabulated for D65
// (green L*a*b* = 87.735, -86.183, 83.179; blue 32.297, 79.188, -107.860): Hunt-adjusted
// HyAB of green against blue, ^0.7, is c_max; a HyAB distance d maps to d^0.7 remapped.
double hand_color_error(double hyab_distance) {
    const double gl = 87.735, ga = -86.183 * 0.87735, gb = 83.179 * 0.87735;
    const double bl = 32.297, ba = 79.188 * 0.32297, bb = -107.860 * 0.32297;
    const double c_max = std::pow(std::abs(gl - bl) + std::hypot(ga - ba, gb - bb), 0.7);
    const double e = std::pow(hyab_distance, 0.7);
    if (e < 0.4 * c_max) return 0.95 / (0.4 * c_max) * e;
    return 0.95 + (e - 0.4 * c_max) / (0.6 * c_max) * 0.05;
}

double lightness(double y) { return 116.0 * std::cbrt(y) - 16.0; }  // y > (6/29)^3

}  // namespace

TEST_CASE("FLIP: identical images give 0 everywhere", "[image][flip]") {
    const Image a = noise(40, 30, 1);
    const FlipResult r = flip(a, a);
    CHECK(r.mean == 0.0);
    CHECK(r.max == 0.0);
    FlipOptions hdr;
    hdr.hdr = true;
    CHECK(flip(noise(40, 30, 2, 8.0f), noise(40, 30, 2, 8.0f), hdr).max == 0.0);
}

TEST_CASE("FLIP: values stay in [0, 1], and pooling is ordered", "[image][flip]") {
    for (unsigned seed = 0; seed < 3; ++seed) {
        const FlipResult r = flip(noise(48, 32, 10 + seed), noise(48, 32, 20 + seed));
        for (float e : r.error) {
            REQUIRE(e >= 0.0f);
            REQUIRE(e <= 1.0f);
        }
        CHECK(r.mean > 0.0);
        CHECK(r.weighted_first_quartile <= r.weighted_median);
        CHECK(r.weighted_median <= r.weighted_third_quartile);
        CHECK(r.weighted_third_quartile <= r.max);
    }
}

TEST_CASE("FLIP colour term: the matrix and white point follow from the sRGB chromaticities", "[image][flip]") {
    const glm::dvec3 white = flip_color::reference_white();
    CHECK(white.x == Approx(0.31271 / 0.32902).epsilon(1e-12));
    CHECK(white.y == Approx(1.0).epsilon(1e-12));
    const glm::dvec3 lab = flip_color::xyz_to_lab(flip_color::linear_rgb_to_xyz({1.0, 1.0, 1.0}));
    CHECK(lab.x == Approx(100.0).epsilon(1e-12));
    CHECK(std::abs(lab.y) < 1e-9);
    const glm::dvec3 back = flip_color::xyz_to_linear_rgb(
        flip_color::ycxcz_to_xyz(flip_color::xyz_to_ycxcz(flip_color::linear_rgb_to_xyz({0.2, 0.5, 0.9}))));
    CHECK(back.z == Approx(0.9).epsilon(1e-12));
}

TEST_CASE("FLIP colour term: HyAB of Hunt-adjusted CIELAB, remapped, on flat images", "[image][flip]") {
    // Flat images: the CSF filters sum to 1 and the feature filters to 0, so FLIP is the colour
    // term of the one colour pair. Grey has a* = b* = 0, so HyAB is |L1 - L2|.
    SECTION("black against white, above the knee: HyAB 100") {
        const FlipResult r = flip(flat(24, 24, glm::vec3(0.0f)), flat(24, 24, glm::vec3(1.0f)));
        CHECK(r.mean == Approx(hand_color_error(100.0)).margin(2e-4));
        CHECK(r.max == Approx(r.mean).margin(1e-6));
    }
    SECTION("two greys, below the knee") {
        const double d = lightness(0.21) - lightness(0.2);
        const FlipResult r = flip(flat(24, 24, glm::vec3(0.2f)), flat(24, 24, glm::vec3(0.21f)));
        CHECK(r.mean == Approx(hand_color_error(d)).margin(2e-4));
    }
    SECTION("green against blue is the largest difference, 1") {
        CHECK(flip_detail::color_error({0, 1, 0}, {0, 0, 1}) == Approx(1.0).margin(1e-12));
    }
    SECTION("a colour difference at equal lightness is the a*b* distance scaled by the Hunt factor") {
        // Red and a grey of red's luminance: same L*, chroma sqrt(a^2 + b^2) of red times L*/100.
        const glm::dvec3 red(1, 0, 0);
        const double y = flip_color::linear_rgb_to_xyz(red).y;
        const glm::dvec3 lab = flip_color::xyz_to_lab(flip_color::linear_rgb_to_xyz(red));
        const double expected = hand_color_error(std::hypot(lab.y, lab.z) * 0.01 * lab.x);
        CHECK(flip_detail::color_error(red, glm::dvec3(y)) == Approx(expected).margin(2e-4));
    }
}

TEST_CASE("FLIP feature term: an edge of height h gives (h / sqrt 2)^0.5 beside it", "[image][flip]") {
    // Columns x < 20 at 0, x >= 20 at h. The edge filter's x factor has positive weights summing
    // to 1 and negative to -1 (zero at the centre), its y factor sums to 1: at x = 19 and x = 20
    // the filter sees all of one sign's weights on the step, a response of magnitude h, where the
    // flat reference gives 0. The point response there is below h (the test checks it is the
    // edge that wins).
    const int w = 40, h = 20;
    const double step = 0.6;
    std::vector<double> flat_y(w * h, 0.0), edge_y(w * h, 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 20; x < w; ++x) edge_y[y * w + x] = step;
    const std::vector<double> f = flip_detail::feature_error(flat_y, edge_y, w, h, 67.0);
    const double expected = std::sqrt(step / std::sqrt(2.0));
    for (int y = 0; y < h; ++y) {
        CHECK(f[y * w + 19] == Approx(expected).epsilon(1e-9));
        CHECK(f[y * w + 20] == Approx(expected).epsilon(1e-9));
        CHECK(f[y * w + 2] == Approx(0.0).margin(1e-12));  // beyond the radius of 9 px: no feature
    }
}

TEST_CASE("FLIP feature term: a point of height h, by hand from the kernels' formulas", "[image][flip]") {
    // sigma = 0.5 * 0.082 * 67 = 2.747 px, radius ceil(3 sigma) = 9. At the point the edge response
    // is 0 (its kernel is 0 at the centre); the point response in x is h * p(0) * g(0), with p(0) =
    // -1 / (sum of |x^2/sigma^2 - 1| g(x) over |x| < sigma, i.e. x = -2..2) and g(0) = 1 / sum g,
    // and the same in y, so the magnitude is sqrt 2 times that and the feature error
    // (h |p(0)| g(0))^0.5.
    const double sigma = 0.5 * 0.082 * 67.0;
    auto g = [&](int x) { return std::exp(-x * x / (2.0 * sigma * sigma)); };
    double negative = 0.0, gauss = 0.0;
    for (int x = -2; x <= 2; ++x) negative += std::abs(x * x / (sigma * sigma) - 1.0) * g(x);
    for (int x = -9; x <= 9; ++x) gauss += g(x);
    const flip_detail::FeatureKernels k = flip_detail::feature_kernels(67.0);
    REQUIRE(k.radius == 9);
    const int w = 31, h = 31;
    const double height = 0.8;
    std::vector<double> flat_y(w * h, 0.2), point_y(w * h, 0.2);
    point_y[15 * w + 15] += height;
    const std::vector<double> f = flip_detail::feature_error(flat_y, point_y, w, h, 67.0);
    CHECK(f[15 * w + 15] == Approx(std::sqrt(height / negative / gauss)).epsilon(1e-9));
}

TEST_CASE("FLIP: a feature difference raises the colour term towards 1", "[image][flip]") {
    // The final error is colour^(1 - feature): an edge that appears makes the error larger than
    // the colour term alone, and a point on a flat image is larger than its blurred colour error.
    Image ref = flat(32, 32, glm::vec3(0.3f)), test = ref;
    test.at(16, 16) = glm::vec3(1.0f);
    const FlipResult r = flip(ref, test);
    CHECK(r.max_x == 16);
    CHECK(r.max_y == 16);
    CHECK(r.max > 0.3);
}

TEST_CASE("FLIP: detail too fine for the viewing distance counts less from further away", "[image][flip]") {
    // A one-pixel checkerboard against its average grey: at more pixels per degree the eye
    // resolves it less and the CSF averages it away.
    Image checker(32, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) checker.at(x, y) = glm::vec3((x + y) % 2 ? 0.8f : 0.2f);
    const Image grey = flat(32, 32, glm::vec3(0.5f));
    FlipOptions near, far;
    near.pixels_per_degree = 20.0;
    far.pixels_per_degree = 120.0;
    CHECK(flip(grey, checker, far).mean < flip(grey, checker, near).mean);
}

TEST_CASE("HDR-FLIP: exposure range from the reference's luminance", "[image][flip]") {
    // Half the pixels at luminance 4, half at 0.25 (grey, so Y is the value): the start exposure
    // brings the brightest to 0.85 after tone mapping, the stop exposure the median.
    Image ref(10, 10);
    for (std::size_t i = 0; i < ref.pixels.size(); ++i) ref.pixels[i] = glm::vec3(i < 60 ? 0.25f : 4.0f);
    double start = 0.0, stop = 0.0;
    flip_detail::automatic_exposures(ref, FlipToneMapper::Aces, start, stop);
    CHECK(flip_detail::tone_map(4.0 * std::exp2(start), FlipToneMapper::Aces) == Approx(0.85).epsilon(1e-6));
    CHECK(flip_detail::tone_map(0.25 * std::exp2(stop), FlipToneMapper::Aces) == Approx(0.85).epsilon(1e-6));
    CHECK(stop - start == Approx(4.0).epsilon(1e-6));  // log2(4 / 0.25)
    FlipOptions hdr;
    hdr.hdr = true;
    Image test = ref;
    test.pixels[0] *= 1.5f;
    const FlipResult r = flip(ref, test, hdr);
    CHECK(r.exposures == 4);  // max(2, ceil(stop - start))
    CHECK(r.start_exposure == Approx(start));
    CHECK(r.max_x == 0);
    CHECK(r.max > 0.0);
}

TEST_CASE("HDR-FLIP: the per-pixel maximum over exposures is at least each exposure's LDR-FLIP", "[image][flip]") {
    const Image ref = noise(24, 24, 5, 6.0f), test = noise(24, 24, 6, 6.0f);
    FlipOptions hdr;
    hdr.hdr = true;
    hdr.start_exposure = -2.0;
    hdr.stop_exposure = 0.0;
    hdr.exposures = 3;
    const FlipResult r = flip(ref, test, hdr);
    FlipOptions one = hdr;
    one.start_exposure = one.stop_exposure = -1.0;
    one.exposures = 1;
    const FlipResult middle = flip(ref, test, one);
    for (std::size_t i = 0; i < r.error.size(); ++i) REQUIRE(r.error[i] >= middle.error[i]);
}

TEST_CASE("FLIP: a very low pixels-per-degree stays finite", "[image][flip]") {
    // At 0.5 ppd the feature Gaussian's neighbours underflow to 0: the kernels must not divide by 0.
    FlipOptions far;
    far.pixels_per_degree = 0.5;
    const FlipResult r = flip(noise(16, 16, 3), noise(16, 16, 4), far);
    for (float e : r.error) REQUIRE(std::isfinite(e));
}

TEST_CASE("FLIP: mismatched sizes and a bad viewing distance are input errors", "[image][flip]") {
    CHECK_THROWS_AS(flip(flat(4, 4, glm::vec3(0)), flat(5, 4, glm::vec3(0))), InputError);
    FlipOptions bad;
    bad.pixels_per_degree = 0.0;
    CHECK_THROWS_AS(flip(flat(4, 4, glm::vec3(0)), flat(4, 4, glm::vec3(0)), bad), InputError);
}

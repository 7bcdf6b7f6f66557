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

// The checks below came from reading NVIDIA's reference implementation (NVlabs/flip v1.6, FLIP.h and
// tool/pooling.h) beside the papers; each expected value is derived by hand in its comment.

TEST_CASE("FLIP: the default viewing distance is the paper's setup, unrounded", "[image][flip]") {
    // 0.7 m from a 0.7 m wide 3840-pixel monitor: 0.7 * (3840 / 0.7) * pi / 180 = 3840 pi / 180
    // = 67.0206 px per degree (the paper prints 67; the reference tool uses this value).
    const FlipOptions defaults;
    CHECK(defaults.pixels_per_degree == Approx(67.02064327658225).epsilon(1e-14));
    // Its filters: CSF radius ceil(3 sqrt(0.04 / (2 pi^2)) 67.02) = ceil(9.05) = 10 is internal;
    // the feature radius ceil(3 * 0.5 * 0.082 * 67.02) = ceil(8.24) = 9.
    CHECK(flip_detail::feature_kernels(defaults.pixels_per_degree).radius == 9);
}

TEST_CASE("FLIP pooling: weighted percentiles take the first error whose running sum exceeds the share",
          "[image][flip]") {
    // Errors (0.25, 0.25, 0.5), total 1. Running sums 0.25, 0.5, 1. Median: 0.5 does not exceed
    // 0.5, so the median is the third value, 0.5 (a ">=" rule would give 0.25). First quartile:
    // 0.25 does not exceed 0.25, 0.5 does: 0.25. Third quartile: 1 > 0.75 first: 0.5.
    FlipResult r;
    r.width = 3;
    r.height = 1;
    r.error = {0.5f, 0.25f, 0.25f};
    flip_detail::pool(r);
    CHECK(r.mean == Approx(1.0 / 3.0).epsilon(1e-12));
    CHECK(r.weighted_median == 0.5);
    CHECK(r.weighted_first_quartile == 0.25);
    CHECK(r.weighted_third_quartile == 0.5);
    CHECK(r.max == 0.5);
    CHECK(r.max_x == 0);
    FlipResult zero;
    zero.width = 2;
    zero.height = 1;
    zero.error = {0.0f, 0.0f};
    flip_detail::pool(zero);
    CHECK(zero.weighted_median == 0.0);
}

TEST_CASE("FLIP: a one-pixel pair is its colour term, by hand through the whole colour pipeline",
          "[image][flip]") {
    // One pixel: every filter tap repeats it (borders clamp), the CSF kernels sum to 1 and the
    // feature kernels see no change, so FLIP = the remapped colour error of the two colours.
    // Reference (0.8, 0.3, 0.1): XYZ (0.455232, 0.391882, 0.146261), Lab (68.8874, 25.3140, 43.9316),
    // Hunt (x 0.688874) a*b* = (17.4382, 30.2634). Test (0.1, 0.5, 0.7): XYZ (0.346350, 0.429381,
    // 0.726792), Lab (71.5130, -20.0738, -23.9006), Hunt (-14.3554, -17.0920).
    // HyAB = 2.62556 + hypot(31.7935, 47.3554) = 59.66377; ^0.7 = 17.49837.
    // c_max = 41.27610, p_c c_max = 16.51044: above the knee, so
    // 0.95 + (17.49837 - 16.51044) / (41.27610 - 16.51044) * 0.05 = 0.951995.
    Image a(1, 1), b(1, 1);
    a.pixels[0] = {0.8f, 0.3f, 0.1f};
    b.pixels[0] = {0.1f, 0.5f, 0.7f};
    const FlipResult r = flip(a, b);
    CHECK(r.mean == Approx(0.9519945).margin(2e-6));
    CHECK(r.weighted_median == Approx(r.mean).margin(1e-7));
}

TEST_CASE("HDR-FLIP: a one-pixel pair, by hand through the exposure range and the ACES curve",
          "[image][flip]") {
    // Reference (4, 2, 1): luminance 0.2126*4 + 0.7152*2 + 0.0722 = 2.353, both its maximum and its
    // median, so start = stop = log2(x85 / 2.353) with ACES(x85) = 0.85: x85 = 2.118872, start =
    // -0.151205, scale 2^start = 0.900498. N = max(2, ceil(0)) = 2 identical exposures.
    // ACES per channel of 0.900498 (4, 2, 1) = (0.923494, 0.819720, 0.641130); of 0.900498 (3, 2.5,
    // 0.5) = (0.888043, 0.860264, 0.401245). Their LDR-FLIP (one pixel: the colour term) is 0.489661.
    Image a(1, 1), b(1, 1);
    a.pixels[0] = {4.0f, 2.0f, 1.0f};
    b.pixels[0] = {3.0f, 2.5f, 0.5f};
    FlipOptions hdr;
    hdr.hdr = true;
    const FlipResult r = flip(a, b, hdr);
    CHECK(r.start_exposure == Approx(-0.1512047).margin(1e-6));
    CHECK(r.stop_exposure == Approx(r.start_exposure).margin(1e-12));
    CHECK(r.exposures == 2);
    CHECK(r.mean == Approx(0.4896610).margin(2e-6));
    Image ta(1, 1), tb(1, 1);
    ta.pixels[0] = {0.923493698f, 0.8197201698f, 0.6411300891f};
    tb.pixels[0] = {0.8880426285f, 0.8602636319f, 0.4012451034f};
    CHECK(flip(ta, tb).mean == Approx(r.mean).margin(1e-6));
}

TEST_CASE("HDR-FLIP: the exposure range uses the luminance 0.2126 R + 0.7152 G + 0.0722 B", "[image][flip]") {
    // A pure red reference of 1: Y = 0.2126 everywhere, so start = stop = log2(x85 / 0.2126), x85
    // the positive root of (k0 - 0.85 k3) x^2 + (k1 - 0.85 k4) x + (k2 - 0.85 k5) for ACES's k.
    Image ref(4, 4);
    for (auto& p : ref.pixels) p = {1.0f, 0.0f, 0.0f};
    const double a = 0.36 * 2.51 - 0.85 * 0.36 * 2.43, b = 0.6 * 0.03 - 0.85 * 0.6 * 0.59, c = -0.85 * 0.14;
    const double x85 = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
    double start = 0.0, stop = 0.0;
    flip_detail::automatic_exposures(ref, FlipToneMapper::Aces, start, stop);
    CHECK(start == Approx(std::log2(x85 / 0.2126)).margin(1e-12));
    CHECK(stop == Approx(start).margin(1e-12));
    CHECK(flip_detail::luminance({1.0, 1.0, 1.0}) == Approx(1.0).margin(1e-15));
}

TEST_CASE("HDR-FLIP: Reinhard divides the whole pixel by 1 + its luminance", "[image][flip]") {
    // (2, 1, 0.5): L = 0.4252 + 0.7152 + 0.0361 = 1.1765, so (2, 1, 0.5) / 2.1765 = (0.918907,
    // 0.459453, 0.229727): the channel ratios stay 4 : 2 : 1 (per-channel x / (1 + x) would give
    // (0.667, 0.5, 0.333)). ACES stays per channel.
    const glm::dvec3 r = flip_detail::tone_map(glm::dvec3(2.0, 1.0, 0.5), FlipToneMapper::Reinhard);
    CHECK(r.x == Approx(2.0 / 2.1765).epsilon(1e-12));
    CHECK(r.y == Approx(1.0 / 2.1765).epsilon(1e-12));
    CHECK(r.z == Approx(0.5 / 2.1765).epsilon(1e-12));
    const glm::dvec3 aces = flip_detail::tone_map(glm::dvec3(2.0, 1.0, 0.5), FlipToneMapper::Aces);
    CHECK(aces.y == Approx(flip_detail::tone_map(1.0, FlipToneMapper::Aces)).epsilon(1e-15));
    // On grey the two forms agree: 3 / (1 + 3) = 0.75.
    CHECK(flip_detail::tone_map(glm::dvec3(3.0), FlipToneMapper::Reinhard).x == Approx(0.75).epsilon(1e-15));
}

TEST_CASE("FLIP: a 7x5 pair matches an independent float64 re-statement of the published algorithm",
          "[image][flip]") {
    // Expected values from a separate NumPy restatement of docs/flip.md (written from the papers and
    // the reference's description, not from this code), at the default 67.0206 ppd. At 7x5 every
    // filter reaches past the border, so this also checks the edge clamping and kernel orientation.
    Image a(7, 5), b(7, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            a.at(x, y) = {0.5 + 0.45 * std::sin(1.3 * x + 0.7 * y), 0.5 + 0.45 * std::sin(0.9 * x - 1.1 * y + 1.0),
                          0.5 + 0.45 * std::cos(0.5 * x + 1.7 * y)};
            b.at(x, y) = {0.5 + 0.45 * std::sin(1.2 * x + 0.8 * y), 0.5 + 0.45 * std::sin(0.9 * x - 1.0 * y + 1.2),
                          0.5 + 0.45 * std::cos(0.6 * x + 1.7 * y)};
        }
    const FlipResult r = flip(a, b);
    CHECK(r.mean == Approx(0.277158318).margin(1e-6));
    CHECK(r.weighted_median == Approx(0.309843973).margin(1e-6));
    CHECK(r.weighted_first_quartile == Approx(0.222691703).margin(1e-6));
    CHECK(r.weighted_third_quartile == Approx(0.391668321).margin(1e-6));
    CHECK(r.max == Approx(0.514894421).margin(1e-6));
    CHECK(r.max_x == 0);
    CHECK(r.max_y == 4);
    Image ha = a, hb = b;  // HDR: 4 v^2 per channel
    for (auto& p : ha.pixels) p = 4.0f * p * p;
    for (auto& p : hb.pixels) p = 4.0f * p * p;
    FlipOptions hdr;
    hdr.hdr = true;
    const FlipResult h = flip(ha, hb, hdr);
    CHECK(h.start_exposure == Approx(-0.692681819).margin(1e-6));
    CHECK(h.stop_exposure == Approx(0.464210690).margin(1e-6));
    CHECK(h.exposures == 2);
    CHECK(h.mean == Approx(0.306290598).margin(1e-6));
}

// Pixel reconstruction filters by filter importance sampling (render/film/pixel_filter.hpp): the
// sampler's integrals against quadrature of the filter, the default box keeping today's jitter,
// and a knife edge (a half-plane emitter seen straight on) whose rendered profile matches the
// convolution of a step with each filter, column by column.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "convergence_harness.hpp"
#include "raytracer/render/film/pixel_filter.hpp"
#include "raytracer/render/sampling/random.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

FilterSpec spec(FilterSpec::Type type, float radius) {
    FilterSpec f;
    f.type = type;
    f.radius = radius;
    return f;
}

// The filters written out again from their definitions (scenes/README.md), independently of
// the sampler's code.
double filter_1d(const FilterSpec& f, double x) {
    const double r = f.radius, a = std::abs(x);
    if (a > r) return 0.0;
    switch (f.type) {
    case FilterSpec::Type::Box: return 1.0;
    case FilterSpec::Type::Tent: return r - a;
    case FilterSpec::Type::Gaussian: {
        const double s = f.sigma;
        return std::exp(-x * x / (2 * s * s)) - std::exp(-r * r / (2 * s * s));
    }
    case FilterSpec::Type::Mitchell: {
        const double t = 2 * a / r, B = f.b, C = f.c;
        if (t < 1) return ((12 - 9 * B - 6 * C) * t * t * t + (-18 + 12 * B + 6 * C) * t * t + (6 - 2 * B)) / 6;
        return ((-B - 6 * C) * t * t * t + (6 * B + 30 * C) * t * t + (-12 * B - 48 * C) * t + (8 * B + 24 * C)) / 6;
    }
    }
    return 0.0;
}

// int_{-r}^{t} g(filter) by composite Simpson, 20000 intervals: error far below 1e-9 for these
// piecewise-smooth integrands (kinks only at 0, the lobes' joins and the radius).
double integral_to(const FilterSpec& f, double t, const std::function<double(double)>& g) {
    const double r = f.radius, hi = std::min(t, r);
    if (hi <= -r) return 0.0;
    constexpr int n = 20000;
    const double h = (hi + r) / n;
    double sum = g(filter_1d(f, -r)) + g(filter_1d(f, hi));
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(filter_1d(f, -r + i * h));
    return sum * h / 3;
}

const std::vector<FilterSpec>& all_filters() {
    static const std::vector<FilterSpec> filters = [] {
        std::vector<FilterSpec> v{spec(FilterSpec::Type::Box, 0.5f), spec(FilterSpec::Type::Box, 1.0f),
                                  spec(FilterSpec::Type::Tent, 1.0f), spec(FilterSpec::Type::Gaussian, 1.5f),
                                  spec(FilterSpec::Type::Mitchell, 2.0f)};
        FilterSpec m = spec(FilterSpec::Type::Mitchell, 1.5f);
        m.b = 0.0f;
        m.c = 0.5f;  // Catmull-Rom: deeper negative lobes
        v.push_back(m);
        return v;
    }();
    return filters;
}

std::string name(const FilterSpec& f) {
    const char* names[] = {"box", "tent", "gaussian", "mitchell"};
    return std::string(names[static_cast<int>(f.type)]) + " r=" + std::to_string(f.radius) + " b=" + std::to_string(f.b);
}

}  // namespace

TEST_CASE("pixel filter: the sampler's CDF and integrals match quadrature of each filter", "[render][filter]") {
    for (const FilterSpec& f : all_filters()) {
        INFO(name(f));
        const PixelFilter pf(f);
        auto absf = [](double v) { return std::abs(v); };
        auto id = [](double v) { return v; };
        // 1e-7: Simpson's error where |f| has a kink off the grid (Mitchell's sign change).
        CHECK(pf.integral_abs() == Approx(integral_to(f, f.radius, absf)).epsilon(1e-7));
        CHECK(pf.integral() == Approx(integral_to(f, f.radius, id)).epsilon(1e-9));
        for (double t = -f.radius; t <= f.radius; t += f.radius / 8)
            CHECK(pf.cdf_abs(t) == Approx(integral_to(f, t, absf)).margin(1e-7));
        // Sampled offsets: their histogram against |f| / int |f| (64 bins, 200k samples), and the
        // mean weight times the mass of each sign.
        constexpr int bins = 64, n = 200000;
        std::vector<int> hist(bins, 0);
        double weight_sum = 0.0;
        Rng rng(7, 0, 0);
        for (int i = 0; i < n; ++i) {
            const FilmOffset o = pf.sample(rng.uniform(), 0.5f);
            const double x = o.dx - 0.5;
            REQUIRE(std::abs(x) <= f.radius * (1 + 1e-6));
            ++hist[std::min(bins - 1, static_cast<int>((x + f.radius) / (2 * f.radius) * bins))];
            weight_sum += o.weight;
        }
        double chi2 = 0.0;
        for (int b = 0; b < bins; ++b) {
            const double lo = -f.radius + 2.0 * f.radius * b / bins, hi = lo + 2.0 * f.radius / bins;
            const double p = (pf.cdf_abs(hi) - pf.cdf_abs(lo)) / pf.integral_abs();
            if (p * n < 5) continue;
            chi2 += (hist[b] - p * n) * (hist[b] - p * n) / (p * n);
        }
        CHECK(chi2 < 130.0);  // 63 degrees of freedom: p ~ 1e-6
        // u2 = 0.5 puts y at the centre (sign +), so a weight is sign(f(x)) k^2, k = int |f| / int f,
        // and E[sign(f(x))] = int f / int |f| = 1 / k: the weights average to k (sd at most k^2).
        const double k = pf.integral_abs() / pf.integral();
        CHECK(pf.sample(0.3f, 0.5f).dy == 0.5f);
        CHECK(weight_sum / n == Approx(k).margin(5.0 * k * k / std::sqrt(double(n))));
    }
}

TEST_CASE("pixel filter: the default box of radius 0.5 is today's jitter, (u1, u2) with weight 1, bit for bit", "[render][filter]") {
    const PixelFilter box;
    Rng rng(3, 1, 2);
    for (int i = 0; i < 1000; ++i) {
        const float u1 = rng.uniform(), u2 = rng.uniform();
        const FilmOffset o = box.sample(u1, u2);
        REQUIRE(o.dx == u1);
        REQUIRE(o.dy == u2);
        REQUIRE(o.weight == 1.0f);
    }
}

namespace {

// Quantile of the standard normal for a two-sided tail p, by bisection on erfc.
double two_sided_z(double p) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
    }
    return lo;
}

// A W x H image of a unit-radiance half-plane emitter facing the camera, covering film x < edge.
Scene knife_edge(int width, int height, double edge, const FilterSpec& f) {
    Scene scene = empty_scene(width, height);
    const float d = 2.0f;
    scene.camera.position = {0.0f, 0.0f, d};
    scene.camera.look_at = glm::vec3(0.0f);
    scene.film.filter = f;
    const double half_w = std::tan(0.5 * glm::radians(double(scene.camera.vfov_degrees))) * width / height;
    const float xw = static_cast<float>((2.0 * edge / width - 1.0) * d * half_w);
    Material lamp;
    lamp.type = Material::Type::Emissive;
    lamp.albedo = glm::vec3(0.0f);
    lamp.emission = glm::vec3(1.0f);
    add_object(scene, collision::Quad{{-100.0f, -100.0f, 0.0f}, {100.0f + xw, 0.0f, 0.0f}, {0.0f, 200.0f, 0.0f}},
               add_material(scene, lamp), glm::mat4(1.0f), "half-plane");
    return scene;
}

struct ColumnTest {
    double max_z = 0.0;
    int worst = -1;
};

// Per column: the mean over its pixels against the step convolved with `truth_filter`
// (int_{-r}^{edge - centre} f / int f), z from the larger of the render's variance and the
// variance a correct render has: a sample reads w = +-k^2 or 0 (k = int |f| / int f), so
// Var = k^4 P_abs - C^2 with P_abs the |f| mass on the lit side.
ColumnTest test_columns(const RenderResult& r, int spp, double edge, const FilterSpec& truth_filter) {
    const double I = integral_to(truth_filter, truth_filter.radius, [](double v) { return v; });
    const double A = integral_to(truth_filter, truth_filter.radius, [](double v) { return std::abs(v); });
    const double k2 = (A / I) * (A / I);
    ColumnTest t;
    for (int x = 0; x < r.image.width; ++x) {
        const double reach = edge - (x + 0.5);
        const double c = integral_to(truth_filter, reach, [](double v) { return v; }) / I;
        const double p_abs = integral_to(truth_filter, reach, [](double v) { return std::abs(v); }) / A;
        const double null_var = std::max(0.0, k2 * k2 * p_abs - c * c) / spp;
        double mean = 0.0, var = 0.0;
        for (int y = 0; y < r.image.height; ++y) {
            mean += r.image.at(x, y).g;
            var += std::max<double>(r.variance.at(x, y).g, null_var);
        }
        mean /= r.image.height;
        const double sigma = std::sqrt(var) / r.image.height;
        // 1e-6 absolute: float rounding of the weight and of the film position.
        const double z = std::max(0.0, std::abs(mean - c) - 1e-6) / std::max(sigma, 1e-12);
        if (z > t.max_z) t.max_z = z, t.worst = x;
    }
    return t;
}

}  // namespace

TEST_CASE("pixel filter: a knife edge renders as the step convolved with each filter, by a z-test per column",
          "[render][filter][convergence]") {
    constexpr int width = 24, height = 16, spp = 256;
    // The edge 0.05 px past a pixel boundary: the columns beside it are where box and tent
    // differ most (0.1), and the default box's are still all lit / nearly all dark.
    const double edge = 12.05;
    const auto& filters = all_filters();
    // Bonferroni over every column of every filter (and the cross-checks below): family-wise 1e-4.
    const double z_limit = two_sided_z(1e-4 / (2.0 * width * filters.size()));
    for (const FilterSpec& f : filters) {
        INFO(name(f) << ", z limit " << z_limit);
        const Scene scene = knife_edge(width, height, edge, f);
        const RenderResult r = render_with(scene, AccelKind::Bvh, spp, 1, 17);
        const ColumnTest t = test_columns(r, spp, edge, f);
        INFO("max z " << t.max_z << " at column " << t.worst);
        CHECK(t.max_z <= z_limit);
        // The test can fail: the same render against another filter's profile is rejected. The
        // other is the default box, except for that box itself and for Catmull-Rom (sharp enough
        // that its profile here is within noise of the box's): the wide Gaussian for those.
        const bool sharp = (f.type == FilterSpec::Type::Box && f.radius == 0.5f) || f.b == 0.0f;
        CHECK(test_columns(r, spp, edge, sharp ? filters[3] : FilterSpec{}).max_z > z_limit);
    }
    // Embree's film positions are the same; its hits agree.
    const FilterSpec mitchell = filters[4];
    const RenderResult e = render_with(knife_edge(width, height, edge, mitchell), AccelKind::Embree, spp, 1, 17);
    CHECK(test_columns(e, spp, edge, mitchell).max_z <= z_limit);
}

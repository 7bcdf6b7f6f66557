// Feature outputs (render --aovs; render/film/sample_features.hpp, image/feature_sums.hpp): the
// features against closed forms (a checker-textured quad's albedo, depth and normal; a sphere's
// normals and albedo seen through a mirror, for every integrator), the exact variance of equal
// samples, the half buffers against the full sums, determinism at 1 and 2 threads, the image
// untouched by them, adaptive sampling's own counts, and bdpt and vcm recording the path tracer's
// quantity (means within noise on a scene with glass, whose delta bounces each integrator draws
// with its own numbers).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "convergence_harness.hpp"
#include "plane_truth.hpp"
#include "raytracer/image/feature_sums.hpp"
#include "raytracer/image/square_sum.hpp"
#include "raytracer/render/renderer.hpp"
#include "render_test_scenes.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

RenderResult render_aovs(const Scene& scene, const Accel& accel, int spp, int max_depth, IntegratorKind integrator,
                         int threads = 0, bool aovs = true) {
    RenderOptions o;
    o.spp = spp;
    o.max_depth = max_depth;
    o.seed = 5;
    o.threads = threads;
    o.integrator = integrator;
    o.aovs = aovs;
    return render(scene, accel, o);
}

const char* name_of(IntegratorKind k) {
    return k == IntegratorKind::Path ? "path" : k == IntegratorKind::Bdpt ? "bdpt" : "vcm";
}

// The mirror scene: the camera at (0, 0, 3) looks down -z at a mirror through the origin whose
// normal is (0, 1, 1) / sqrt 2, which sends its rays up (+y) to a diffuse sphere at (0, 2, 0),
// out of the camera's direct view (33.7 degrees up, the half field of view 25).
constexpr int kMirrorSize = 32;
const glm::dvec3 kSphereCentre(0.0, 2.0, 0.0);
constexpr double kSphereRadius = 0.6;
const glm::vec3 kSphereAlbedo(0.2f, 0.5f, 0.9f);

Scene mirror_scene() {
    Scene scene = empty_scene(kMirrorSize, kMirrorSize);
    scene.camera.position = {0.0f, 0.0f, 3.0f};
    scene.camera.vfov_degrees = 50.0f;
    scene.background.color = glm::vec3(0.5f);  // some light for bdpt's and vcm's light subpaths
    Material mirror;
    mirror.type = Material::Type::Metal;
    mirror.roughness = 0.0f;
    mirror.albedo = glm::vec3(0.9f);
    add_object(scene, collision::Quad{{-1.0f, -0.8f, 0.8f}, {2.0f, 0.0f, 0.0f}, {0.0f, 1.6f, -1.6f}},
               add_material(scene, mirror), glm::mat4(1.0f), "mirror");
    add_object(scene, collision::Sphere{glm::vec3(kSphereCentre), static_cast<float>(kSphereRadius)},
               add_material(scene, test::diffuse(kSphereAlbedo)), glm::mat4(1.0f), "sphere");
    return scene;
}

// The sphere's outward normal where film position (fx, fy)'s ray meets it after the mirror, in
// double; false when the ray misses the mirror or the reflected ray misses the sphere.
bool normal_through_mirror(const PinholeRays& cam, double fx, double fy, glm::dvec3& normal) {
    const glm::dvec3 d = glm::normalize(cam.direction(fx, fy));
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.0, 1.0, 1.0));
    const double dn = glm::dot(d, n);
    if (dn >= 0.0) return false;
    const double t = -glm::dot(cam.eye, n) / dn;  // the mirror's plane goes through the origin
    const glm::dvec3 p = cam.eye + t * d;
    if (std::abs(p.x) > 1.0 || std::abs(p.y) > 0.8) return false;  // outside the quad
    const glm::dvec3 r = d - 2.0 * dn * n;
    const glm::dvec3 oc = p - kSphereCentre;
    const double b = glm::dot(oc, r), c = glm::dot(oc, oc) - kSphereRadius * kSphereRadius;
    const double disc = b * b - c;
    if (disc < 0.0) return false;
    const double s = -b - std::sqrt(disc);
    if (s <= 0.0) return false;
    normal = glm::normalize(p + s * r - kSphereCentre);
    return true;
}

}  // namespace

TEST_CASE("aovs: variance of the mean from exact sums is 0 for equal samples and the sample variance otherwise", "[render][aovs]") {
    SquareSum q;
    SumInt s = 0;
    bool clamped = false;
    for (int i = 0; i < 7; ++i) {
        const SumInt x = to_fixed(0.7f, clamped);
        s += x;
        add_square(q, x);
    }
    CHECK(variance_of_mean(s, q, 7) == 0.0);  // a double Q/n - mean^2 leaves rounding noise here
    SquareSum q2;
    SumInt s2 = 0;
    for (float v : {1.0f, 2.0f, 3.0f, 4.0f, -2.5f}) {
        const SumInt x = to_fixed(v, clamped);
        s2 += x;
        add_square(q2, x);
    }
    // mean 1.5, squares 30 + 6.25: sample variance (36.25 - 5 * 2.25) / 4 = 6.25, over n = 5.
    CHECK(variance_of_mean(s2, q2, 5) == Approx(1.25).epsilon(1e-15));
    // The largest sample the fixed point holds, squared, stays exact in 256 bits.
    SquareSum big;
    const SumInt m = to_fixed(kSampleLimit, clamped);
    add_square(big, m);
    add_square(big, -m);
    CHECK(variance_of_mean(0, big, 2) == Approx(2.0 * double(kSampleLimit) * double(kSampleLimit) / 2.0).epsilon(1e-15));
}

TEST_CASE("aovs: feature sums at the ends of their ranges stay exact, and beyond them are clamped", "[render][aovs]") {
    // Albedo 1 and normal -1 are 2^32 on the 2^-32 grid, their squares 2^64: the 64-bit sums and
    // 128-bit squares must hold them exactly (a square kept in 64 bits would wrap to 0).
    FeatureSums s;
    FeatureSample f;
    f.color = glm::vec3(0.5f, 3.0f, 1000.0f);
    f.features.albedo = glm::vec3(1.0f, 0.25f, 1.5f);   // 1.5: clamped to 1
    f.features.normal = glm::vec3(-1.0f, 0.0f, 1.0f);
    f.features.position = glm::vec3(-3.0f, 0x1p31f, 1.0e9f);  // y beyond kFeaturePositionLimit
    constexpr int n = 1001;
    for (int i = 0; i < n; ++i) add_feature_sample(s, i, f);
    CHECK(s.count[0] == 501);
    CHECK(s.count[1] == 500);
    CHECK(s.albedo[0].v[0] == std::int64_t{501} << 32);
    CHECK(s.bounded_square[0] == static_cast<SumUInt>(n) << 64);
    const FeatureLayers L = feature_layers({s}, 1, 1);
    CHECK(L.color.pixels[0] == f.color);
    CHECK(L.albedo.pixels[0] == glm::vec3(1.0f, 0.25f, 1.0f));
    CHECK(L.normal.pixels[0] == f.features.normal);
    CHECK(L.position.pixels[0] == glm::vec3(-3.0f, kFeaturePositionLimit, 1.0e9f));
    for (int h = 0; h < 2; ++h) CHECK(L.half_normal[h].pixels[0] == f.features.normal);
    // Equal samples: every variance exactly 0.
    CHECK(L.color_variance.pixels[0] == glm::vec3(0.0f));
    CHECK(L.albedo_variance.pixels[0] == glm::vec3(0.0f));
    CHECK(L.normal_variance.pixels[0] == glm::vec3(0.0f));
    CHECK(L.depth_variance[0] == 0.0f);
    // Two values of the bounded features and of depth: the unbiased variance of the mean.
    FeatureSums t;
    FeatureSample g = f;
    for (int i = 0; i < 4; ++i) {
        g.features.normal.x = i % 2 == 0 ? -1.0f : 1.0f;    // mean 0, sample variance 4/3
        g.features.position.z = i % 2 == 0 ? 1.0e9f : 0.0f;  // sample variance 1e18/3
        add_feature_sample(t, i, g);
    }
    const FeatureLayers T = feature_layers({t}, 1, 1);
    CHECK(T.normal.pixels[0].x == 0.0f);
    CHECK(T.normal_variance.pixels[0].x == Approx(1.0 / 3.0).epsilon(1e-7));
    CHECK(T.depth_variance[0] == Approx(1.0e18 / 12.0).epsilon(1e-7));
}

TEST_CASE("aovs: the conversions' fast paths give the sums of the plain definition, at every magnitude", "[render][aovs]") {
    // add_feature_sample converts a colour of magnitude 0 or [2^-33, 2^7) by one truncation and
    // the features by pairs of doubles (feature_sums.cpp); its sums must be those of the plain
    // definition: to_fixed and add_square for the colour, round to nearest (ties to even) on the
    // 2^-32 grid after the clamps for the features. Samples over every binary exponent from
    // denormals to past the clamps, both signs, mantissas at the ends and random, one sample a
    // pixel so that a mismatch shows in the pixel that made it.
    std::mt19937 rng(5);
    std::uniform_int_distribution<std::uint32_t> mantissa(0, (1u << 23) - 1);
    std::vector<float> values{0.0f, -0.0f};
    for (std::uint32_t exponent = 0; exponent <= 127 + 42; ++exponent)
        for (std::uint32_t m : {0u, 1u, (1u << 22) + 1, (1u << 23) - 1, mantissa(rng), mantissa(rng)})
            for (std::uint32_t sign : {0u, 1u}) values.push_back(std::bit_cast<float>(sign << 31 | exponent << 23 | m));
    const auto nearest = [](float v, float limit) {  // the plain definition of a feature's fixed point
        const double c = std::clamp(static_cast<double>(v), -static_cast<double>(limit), static_cast<double>(limit));
        return static_cast<std::int64_t>(std::nearbyint(c * 0x1p32));
    };
    std::size_t mismatched = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        FeatureSample f;
        // Each value in every channel, beside others of the list (so both position paths run).
        const float v = values[i], w = values[(i * 7 + 3) % values.size()], u = values[(i * 13 + 5) % values.size()];
        f.color = glm::vec3(v, w, u);
        f.features.albedo = glm::vec3(w, v, u);
        f.features.normal = glm::vec3(u, w, v);
        f.features.position = glm::vec3(v, u, w);
        FeatureSums got;
        add_feature_sample(got, static_cast<std::int64_t>(i), f);
        FeatureSums want;
        const int h = static_cast<int>(i & 1);
        want.count[h] = 1;
        for (int c = 0; c < 3; ++c) {
            bool clamped = false;
            const SumInt x = to_fixed(f.color[c], clamped);
            want.color[h].rgb[c] = x;
            add_square(want.color_square[c], x);
            const std::int64_t a = nearest(f.features.albedo[c], 1.0f), n = nearest(f.features.normal[c], 1.0f);
            want.albedo[h].v[c] = a;
            want.normal[h].v[c] = n;
            want.bounded_square[c] = static_cast<SumUInt>(static_cast<SumInt>(a) * a);
            want.bounded_square[3 + c] = static_cast<SumUInt>(static_cast<SumInt>(n) * n);
            want.position[h].rgb[c] = nearest(f.features.position[c], kFeaturePositionLimit);
        }
        add_square(want.depth_square, want.position[h].rgb[2]);
        mismatched += got == want ? 0 : 1;
    }
    CHECK(values.size() > 2000);
    CHECK(mismatched == 0);
}

TEST_CASE("aovs: a batch of consecutive samples gives the sums of the samples added one by one", "[render][aovs]") {
    // add_feature_samples sums a full batch of plain colours in registers, two samples to each
    // half, and takes anything else sample by sample: on sums that already hold samples, for
    // batches of 1 to 4 starting at even and odd indices, with colours plain and not (a large,
    // a tiny, a negative value), positions on both conversion paths and values at the clamps.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const auto sample = [&](int kind) {
        FeatureSample f;
        f.color = glm::vec3(std::abs(u(rng)) * 3.0f, std::abs(u(rng)), 0.25f);
        if (kind == 1) f.color.x = 1.0e9f;                         // past 2^7: to_fixed's general case
        if (kind == 2) f.color.y = 1.0e-12f;                       // below 2^-33: rounded
        if (kind == 3) f.color.z = -2.5f;                          // a negative lobe of the filter
        f.features.albedo = glm::vec3(std::abs(u(rng)), 1.0f, 0.0f);  // 1 squares to 2^64
        f.features.normal = glm::vec3(u(rng), -1.0f, u(rng));
        f.features.position = glm::vec3(u(rng) * 50.0f, u(rng), kind == 4 ? 3.0e6f : 10.0f + u(rng));  // 3e6: one by one
        return f;
    };
    std::size_t batches = 0, mismatched = 0;
    for (int n = 1; n <= kFeatureBatch; ++n)
        for (std::int64_t first : {0, 1, 6, 7})
            for (int odd_kind = 0; odd_kind <= 4; ++odd_kind) {  // 0: every colour plain
                FeatureSums one_by_one, batched;
                for (int k = 0; k < 3; ++k) {  // earlier samples, so carries meet sums that are not zero
                    const FeatureSample f = sample(0);
                    add_feature_sample(one_by_one, k, f);
                    add_feature_sample(batched, k, f);
                }
                std::vector<FeatureSample> fs;
                for (int k = 0; k < n; ++k) fs.push_back(sample(k == n / 2 ? odd_kind : 0));
                for (int k = 0; k < n; ++k) add_feature_sample(one_by_one, first + k, fs[static_cast<std::size_t>(k)]);
                add_feature_samples(batched, first, fs.data(), n);
                ++batches;
                mismatched += batched == one_by_one ? 0 : 1;
            }
    CHECK(batches == 80);
    CHECK(mismatched == 0);
    // A batch's squares past 2^128 carry into the upper limbs as one by one: four colours near
    // 2^7 square to nearly 2^126 each on the 2^-56 grid.
    FeatureSums one_by_one, batched;
    std::vector<FeatureSample> big(kFeatureBatch);
    for (FeatureSample& f : big) f.color = glm::vec3(127.99f, 100.0f, 64.0f);
    for (int round = 0; round < 3; ++round) {
        for (int k = 0; k < kFeatureBatch; ++k) add_feature_sample(one_by_one, 4 * round + k, big[static_cast<std::size_t>(k)]);
        add_feature_samples(batched, 4 * round, big.data(), kFeatureBatch);
    }
    CHECK(batched.color_square[0].limb[2] != 0);
    CHECK(batched == one_by_one);
}

TEST_CASE("aovs: a checker-textured quad's albedo, normal and depth against the closed form, misses zero", "[render][aovs]") {
    constexpr int size = 32, sub = 8;
    Scene scene = plane_test_scene(size);
    const Texture checker = plane_checker();
    scene.textures.push_back(checker);
    Material m = diffuse(0.0f);
    m.albedo_texture = 0;
    add_object(scene, collision::Quad{glm::vec3(0.0f), {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, add_material(scene, m),
               checker_square_placement(), "q");
    // Region 0/1: the checker's colours, 2: the background (a miss: albedo 0).
    const PlaneTruth truth = plane_truth(size, sub, checker_square_region,
                                         [&](int cell) { return cell == 2 ? glm::vec3(0.0f) : cell == 0 ? checker.a : checker.b; });
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const RenderResult r = render_aovs(scene, *accel, 6, 1, IntegratorKind::Path);
    REQUIRE(r.features.size() == r.sums.size());
    const FeatureLayers L = feature_layers(r.features, size, size);
    int on_quad = 0, missed = 0, edges_with_variance = 0;
    for (std::size_t i = 0; i < L.albedo.pixels.size(); ++i) {
        if (!truth.mask[i]) {
            edges_with_variance += L.albedo_variance.pixels[i].x > 0.0f ? 1 : 0;
            continue;
        }
        INFO("pixel " << i);
        // Every sample of a masked pixel reads the same texel value: its mean is that value
        // exactly, and its variance exactly 0 (the exact sums of squares).
        CHECK(L.albedo.pixels[i] == truth.image.pixels[i]);
        CHECK(L.albedo_variance.pixels[i] == glm::vec3(0.0f));
        if (truth.image.pixels[i] == glm::vec3(0.0f)) {
            ++missed;
            CHECK(L.normal.pixels[i] == glm::vec3(0.0f));
            CHECK(L.position.pixels[i] == glm::vec3(0.0f));
        } else {
            ++on_quad;
            // The plane z = 0 faces the camera at (0, 0, 3): normal +z, depth 3 everywhere.
            CHECK(glm::length(L.normal.pixels[i] - glm::vec3(0.0f, 0.0f, 1.0f)) < 1e-6f);
            CHECK(std::abs(L.position.pixels[i].z - 3.0f) < 1e-5f);
            CHECK(L.depth_variance[i] < 1e-10f);
        }
    }
    CHECK(on_quad > 300);
    CHECK(missed > 100);
    CHECK(edges_with_variance > 20);  // pixels straddling an edge mix two values
}

TEST_CASE("aovs: a sphere seen through a mirror gives its own normals and albedo, for every integrator", "[render][aovs]") {
    const Scene scene = mirror_scene();
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const PinholeRays cam(scene.camera, kMirrorSize, kMirrorSize);
    // Truth per pixel: the mean over an 8 x 8 grid of its film positions; only pixels all of
    // whose positions see the sphere in the mirror.
    constexpr int sub = 8;
    std::vector<glm::dvec3> truth(static_cast<std::size_t>(kMirrorSize) * kMirrorSize);
    std::vector<std::uint8_t> inside(truth.size(), 1);
    for (int y = 0; y < kMirrorSize; ++y)
        for (int x = 0; x < kMirrorSize; ++x) {
            glm::dvec3 sum(0.0);
            const std::size_t i = static_cast<std::size_t>(y) * kMirrorSize + x;
            for (int j = 0; j < sub && inside[i]; ++j)
                for (int k = 0; k < sub; ++k) {
                    glm::dvec3 n;
                    if (!normal_through_mirror(cam, x + (k + 0.5) / sub, y + (j + 0.5) / sub, n)) {
                        inside[i] = 0;
                        break;
                    }
                    sum += n;
                }
            truth[i] = sum / double(sub * sub);
        }
    for (IntegratorKind k : {IntegratorKind::Path, IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        INFO(name_of(k));
        // max_depth 2: the sphere is the second vertex, recorded though the path ends there.
        const RenderResult r = render_aovs(scene, *accel, 16, 2, k);
        const FeatureLayers L = feature_layers(r.features, kMirrorSize, kMirrorSize);
        int tested = 0;
        double worst_z = 0.0;
        for (std::size_t i = 0; i < truth.size(); ++i) {
            if (!inside[i]) continue;
            ++tested;
            INFO("pixel " << i);
            CHECK(L.albedo.pixels[i] == kSphereAlbedo);  // the sphere's, not the mirror's 0.9
            for (int c = 0; c < 3; ++c) {
                // The mean of 16 samples against the 64-point quadrature of the same pixel: within
                // 5 standard errors (the variance of the mean, overstated under Sobol), plus the
                // float rounding of a unit vector.
                const double sigma = std::sqrt(double(L.normal_variance.pixels[i][c]));
                const double d = std::abs(double(L.normal.pixels[i][c]) - truth[i][c]);
                CHECK(d <= 5.0 * sigma + 1e-5);
                if (sigma > 0.0) worst_z = std::max(worst_z, d / sigma);
            }
        }
        INFO("largest |z| " << worst_z);
        CHECK(tested >= 40);  // the pixels whose every film position sees the sphere in the mirror
    }
}

TEST_CASE("aovs: half buffers add up to the full sums exactly, 1 and 2 threads bit-identical, the image untouched", "[render][aovs]") {
    const Scene scene = test::two_light_scene(24, 18);
    const test::DoublePrecisionAccel accel(scene);
    for (IntegratorKind k : {IntegratorKind::Path, IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        INFO(name_of(k));
        const RenderResult one = render_aovs(scene, accel, 5, 4, k, 1);
        const RenderResult two = render_aovs(scene, accel, 5, 4, k, 2);
        const RenderResult plain = render_aovs(scene, accel, 5, 4, k, 2, false);
        CHECK(plain.features.empty());
        CHECK(one.features == two.features);
        CHECK(one.sums == plain.sums);  // recording features changes no sample
        CHECK(same_bits(one.image, plain.image));
        const FeatureLayers L = feature_layers(one.features, 24, 18);
        bool halves_differ = false;
        for (std::size_t i = 0; i < one.sums.size(); ++i) {
            const FeatureSums& f = one.features[i];
            REQUIRE(f.count[0] == 3);  // samples 0, 2, 4
            REQUIRE(f.count[1] == 2);  // samples 1, 3
            PixelSum whole = f.color[0];
            whole += f.color[1];
            CHECK(whole == one.sums[i]);
            // The float means: (3 even + 2 odd) / 5 is the full mean up to their roundings.
            for (int c = 0; c < 3; ++c) {
                const double full = L.color.pixels[i][c];
                const double mix = (3.0 * L.half_color[0].pixels[i][c] + 2.0 * L.half_color[1].pixels[i][c]) / 5.0;
                CHECK(std::abs(mix - full) <= 1e-6 * std::max(1.0, std::abs(full)));
            }
            CHECK(L.color.pixels[i] == one.image.pixels[i]);
            halves_differ = halves_differ || L.half_color[0].pixels[i] != L.half_color[1].pixels[i];
        }
        CHECK(halves_differ);  // two halves of noise, not one buffer twice
    }
}

TEST_CASE("aovs: under adaptive sampling each pixel's halves hold its own count", "[render][aovs]") {
    const Scene scene = test::two_light_scene(24, 18);
    const test::DoublePrecisionAccel accel(scene);
    RenderOptions o;
    o.spp = 40;
    o.max_depth = 4;
    o.adaptive = true;
    o.aovs = true;
    const RenderResult r = render(scene, accel, o);
    REQUIRE(r.pixel_samples.size() == r.sums.size());
    bool uneven = false;
    for (std::size_t i = 0; i < r.sums.size(); ++i) {
        const FeatureSums& f = r.features[i];
        const int n = r.pixel_samples[i];
        CHECK(f.count[0] == (n + 1) / 2);  // samples 0 .. n-1 of its own sequence
        CHECK(f.count[1] == n / 2);
        PixelSum whole = f.color[0];
        whole += f.color[1];
        CHECK(whole == r.sums[i]);
        uneven = uneven || n != r.pixel_samples[0];
    }
    CHECK(uneven);
}

TEST_CASE("aovs: bdpt and vcm record the path tracer's features (means within noise, through glass)", "[render][aovs]") {
    Scene scene = test::two_light_scene(32, 24);
    Material glass;
    glass.type = Material::Type::Dielectric;
    glass.ior = 1.5f;
    test::add_object(scene, collision::Sphere{{0.1f, 1.5f, 1.2f}, 0.5f}, test::add_material(scene, glass));
    const test::DoublePrecisionAccel accel(scene);
    auto layer_means = [&](IntegratorKind k, std::vector<double>& mean, std::vector<double>& var) {
        const RenderResult r = render_aovs(scene, accel, 32, 6, k, 0);
        const FeatureLayers L = feature_layers(r.features, 32, 24);
        const double n = double(L.albedo.pixels.size());
        mean.assign(10, 0.0);
        var.assign(10, 0.0);
        for (std::size_t i = 0; i < L.albedo.pixels.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                mean[c] += L.albedo.pixels[i][c] / n;
                var[c] += L.albedo_variance.pixels[i][c] / (n * n);
                mean[3 + c] += L.normal.pixels[i][c] / n;
                var[3 + c] += L.normal_variance.pixels[i][c] / (n * n);
            }
            mean[6] += L.position.pixels[i].z / n;
            var[6] += L.depth_variance[i] / (n * n);
        }
        mean.resize(7);
        var.resize(7);
    };
    std::vector<double> path_mean, path_var;
    layer_means(IntegratorKind::Path, path_mean, path_var);
    CHECK(path_var[6] > 0.0);  // the glass splits pixels between reflection and refraction
    for (IntegratorKind k : {IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        INFO(name_of(k));
        std::vector<double> mean, var;
        layer_means(k, mean, var);
        for (int c = 0; c < 7; ++c) {
            INFO("channel " << c << ": path " << path_mean[c] << ", " << name_of(k) << " " << mean[c]);
            const double sigma = std::sqrt(path_var[c] + var[c]);
            CHECK(std::abs(mean[c] - path_mean[c]) <= 5.0 * sigma + 1e-6 * std::abs(path_mean[c]));
        }
    }
}

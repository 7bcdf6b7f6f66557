// The renderer end to end on small scenes built in code: analytic truths (furnace, emissive
// enclosure), the two estimators agreeing, determinism across thread counts, cancellation.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "raytracer/render/planted_defect.hpp"
#include "raytracer/render/renderer.hpp"
#include "cancel_at_ray.hpp"
#include "render_test_scenes.hpp"
#include "render_test_stats.hpp"

using namespace sweeptrace;
using sweeptrace::test::DoublePrecisionAccel;
using sweeptrace::test::z_bound;

namespace {

// A diffuse sphere (albedo rho) filling the middle of a 16x16 view, in a constant environment.
Scene furnace_scene(glm::vec3 rho, glm::vec3 env) {
    Scene s;
    s.film.width = 16;
    s.film.height = 16;
    s.camera.position = {0.0f, 0.0f, 4.0f};
    s.camera.look_at = {0.0f, 0.0f, 0.0f};
    s.camera.vfov_degrees = 35.0f;
    s.background.kind = Background::Kind::Constant;
    s.background.color = env;
    s.materials.push_back(test::diffuse(rho));
    test::add_object(s, collision::Sphere{{0.0f, 0.0f, 0.0f}, 1.0f}, 0);
    return s;
}

// Pixels of the furnace view whose every camera ray hits the sphere: the pixel's farthest corner
// from the centre must be inside the silhouette (sin of half-angle = 1/4 at distance 4).
bool fully_covered(const Scene& s, int x, int y) {
    const float half = std::tan(0.5f * s.camera.vfov_degrees * 3.14159265f / 180.0f);
    const float cx = std::max(std::abs(x - 8.0f), std::abs(x + 1 - 8.0f)) / 8.0f * half;
    const float cy = std::max(std::abs(y - 8.0f), std::abs(y + 1 - 8.0f)) / 8.0f * half;
    const float tan2 = cx * cx + cy * cy;
    return tan2 < 0.95f * (1.0f / 15.0f);  // tan^2 of the silhouette: sin^2 / cos^2 = (1/16) / (15/16)
}

RenderOptions options(int spp, std::uint64_t seed = 1) {
    RenderOptions o;
    o.spp = spp;
    o.seed = seed;
    o.threads = 2;
    return o;
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

glm::dvec3 image_mean(const Image& img) {
    glm::dvec3 m(0.0);
    for (const glm::vec3& p : img.pixels) m += glm::dvec3(p);
    return m / double(img.pixels.size());
}

}  // namespace

TEST_CASE("render: white furnace, a convex diffuse sphere reads rho L at every covered pixel", "[render][furnace]") {
    const glm::vec3 rho(0.6f, 0.3f, 0.9f), env(1.0f, 2.0f, 0.5f);
    const Scene s = furnace_scene(rho, env);
    const DoublePrecisionAccel accel(s);
    for (Sampling mode : {Sampling::NeeMis, Sampling::BsdfOnly}) {
        RenderOptions o = options(8);
        o.sampling = mode;
        const RenderResult r = render(s, accel, o);
        int covered = 0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                if (!fully_covered(s, x, y)) continue;
                ++covered;
                // Every sample is exactly rho * L (one product; the reflected ray escapes a
                // convex shape), so the mean is too, to the rounding of an 8-term sum.
                const glm::vec3 v = r.image.at(x, y);
                REQUIRE(glm::length(v - rho * env) < 1e-6f);
            }
        CHECK(covered >= 40);
        CHECK(r.image.at(0, 0) == env);  // background in the corner
    }
}

TEST_CASE("render: max_depth 1 shows only emitters and the background", "[render][depth]") {
    const Scene s = furnace_scene(glm::vec3(0.5f), glm::vec3(1.0f));
    const DoublePrecisionAccel accel(s);
    RenderOptions o = options(2);
    o.max_depth = 1;
    const RenderResult r = render(s, accel, o);
    CHECK(r.image.at(8, 8) == glm::vec3(0.0f));
    CHECK(r.image.at(0, 0) == glm::vec3(1.0f));
}

TEST_CASE("render: the planted NoRayOffset defect makes surfaces re-hit themselves (acne)", "[render][defect]") {
    const Scene s = furnace_scene(glm::vec3(0.8f), glm::vec3(1.0f));
    const DoublePrecisionAccel accel(s);
    RenderOptions o = options(16);
    const RenderResult r = render_with_planted_defect(s, accel, o, PlantedDefect::NoRayOffset);
    // Without offset, about half the reflected rays start inside the sphere (the point is rounded
    // to float) and re-hit it: the covered pixels go visibly darker than rho L = 0.8.
    CHECK(r.image.at(8, 8).r < 0.76f);
}

TEST_CASE("render: inside a closed emissive diffuse sphere, radiance is Le (1 - rho^D) / (1 - rho)", "[render][enclosure]") {
    // Every path vertex sees emission Le; each bounce multiplies by rho; depth D truncates the sum
    // after D vertices. Both estimators and the one-sided case are checked.
    const float rho = 0.5f, le = 1.0f;
    const int depth = 5;
    Scene s;
    s.film.width = 12;
    s.film.height = 12;
    s.camera.position = {0.1f, -0.2f, 0.3f};
    s.camera.look_at = {0.0f, 0.0f, -1.0f};
    s.camera.vfov_degrees = 90.0f;
    Material m = test::diffuse(glm::vec3(rho), glm::vec3(le));
    m.two_sided_emission = true;
    s.materials.push_back(m);
    test::add_object(s, collision::Sphere{{0.0f, 0.0f, 0.0f}, 1.0f}, 0);
    const DoublePrecisionAccel accel(s);
    const double expected = le * (1.0 - std::pow(rho, depth)) / (1.0 - rho);
    for (Sampling mode : {Sampling::NeeMis, Sampling::BsdfOnly}) {
        INFO((mode == Sampling::NeeMis ? "NEE+MIS" : "BSDF only"));
        RenderOptions o = options(16, 5);
        o.sampling = mode;
        o.max_depth = depth;
        const RenderResult r = render(s, accel, o);
        double mean = 0.0, var = 0.0;
        const double n = double(r.image.pixels.size());
        for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
            mean += r.image.pixels[i].g / n;
            var += r.variance.pixels[i].g / (n * n);  // pixels are independent
        }
        CHECK(var > 0.0);
        CHECK(std::abs(mean - expected) < z_bound(2) * std::sqrt(var));
    }
    s.materials[0].two_sided_emission = false;  // the inside is the back: nothing is emitted
    CHECK(image_mean(render(s, accel, options(2)).image) == glm::dvec3(0.0));
}

TEST_CASE("render: NEE+MIS and BSDF-only sampling converge to the same image (quad and sphere lights)", "[render][mis]") {
    const Scene s = test::two_light_scene(24, 18);
    const DoublePrecisionAccel accel(s);
    RenderOptions a = options(128, 11);
    RenderOptions b = options(1024, 12);
    b.sampling = Sampling::BsdfOnly;
    const RenderResult ra = render(s, accel, a), rb = render(s, accel, b);
    // 6x6-pixel blocks: 12 blocks x 3 channels = 36 z-tests on block means, with the variance of
    // each block mean the sum of its pixels' estimated variances over 36^2.
    const int bs = 6;
    const auto worst_z = [&](float scale_b) {
        double worst = 0.0;
        for (int by = 0; by < 18 / bs; ++by)
            for (int bx = 0; bx < 24 / bs; ++bx)
                for (int c = 0; c < 3; ++c) {
                    double ma = 0, mb = 0, va = 0, vb = 0;
                    for (int y = by * bs; y < (by + 1) * bs; ++y)
                        for (int x = bx * bs; x < (bx + 1) * bs; ++x) {
                            ma += ra.image.at(x, y)[c];
                            mb += scale_b * rb.image.at(x, y)[c];
                            va += ra.variance.at(x, y)[c];
                            vb += scale_b * scale_b * rb.variance.at(x, y)[c];
                        }
                    const double z = std::abs(ma - mb) / std::sqrt(va + vb);
                    worst = std::max(worst, z);
                }
        return worst;
    };
    const double z = worst_z(1.0f);
    INFO("worst |z| over 36 block means: " << z);
    CHECK(z < z_bound(36));
    // The comparison has power: a 10% brightness error in one estimator is rejected.
    CHECK(worst_z(0.9f) > z_bound(36));
    // NEE+MIS is the better estimator here: lower variance per sample, summed over the image.
    double va = 0, vb = 0;
    for (std::size_t i = 0; i < ra.variance.pixels.size(); ++i) {
        va += ra.variance.pixels[i].g * a.spp;
        vb += rb.variance.pixels[i].g * b.spp;
    }
    CHECK(va < vb);
}

TEST_CASE("render: the image is identical bit for bit at 1, 2 and 3 threads, with or without progress", "[render][determinism]") {
    const Scene s = test::two_light_scene(37, 21);  // not a multiple of the tile size
    const DoublePrecisionAccel accel(s);
    RenderOptions o = options(3, 42);
    o.threads = 1;
    const RenderResult one = render(s, accel, o);
    o.threads = 2;
    const RenderResult two = render(s, accel, o);
    o.threads = 3;
    int calls = 0;
    double last = -1.0;
    bool monotone = true;
    o.progress = [&](const RenderProgress& p) {
        const double f = p.fraction;
        monotone = monotone && f >= last && f <= 1.0;
        last = f;
        ++calls;
    };
    const RenderResult three = render(s, accel, o);
    CHECK(same_bits(one.image, two.image));
    CHECK(same_bits(one.image, three.image));
    CHECK(same_bits(one.variance, three.variance));
    CHECK(calls >= 1);
    CHECK(monotone);
    CHECK(last == 1.0);
    CHECK(one.stats.samples == 37u * 21u * 3u);
    CHECK(one.stats.rays >= one.stats.samples);
    CHECK(one.stats.rays == three.stats.rays);
    CHECK(one.stats.nonfinite_samples == 0u);
    CHECK_FALSE(one.stats.cancelled);
    o.seed = 43;
    CHECK_FALSE(same_bits(one.image, render(s, accel, o).image));
}

TEST_CASE("render: a cancelled render returns whole passes: the image of spp = completed_spp", "[render][cancel]") {
    const Scene s = test::two_light_scene(20, 20);
    const DoublePrecisionAccel accel(s);
    RenderOptions o = options(10, 3);
    const RenderResult full = render(s, accel, o);
    const std::uint64_t rays_per_pass = full.stats.rays / 10;
    for (int threads : {1, 2}) {
        std::atomic<bool> cancel{false};
        const test::CancelAtRay cancelling(accel, cancel, rays_per_pass * 5 / 2);  // mid third pass
        o.cancel = &cancel;
        o.threads = threads;
        o.spp = 10;
        const RenderResult r = render(s, cancelling, o);
        CHECK(r.stats.cancelled);
        REQUIRE(r.stats.completed_spp >= 1);
        CHECK(r.stats.completed_spp < 10);
        CHECK(r.stats.samples == 400u * r.stats.completed_spp);
        RenderOptions ref = options(r.stats.completed_spp, 3);
        CHECK(same_bits(r.image, render(s, accel, ref).image));
    }
    std::atomic<bool> early{true};
    o.cancel = &early;
    const RenderResult none = render(s, accel, o);
    CHECK(none.stats.cancelled);
    CHECK(none.stats.completed_spp == 0);
    CHECK(none.image.width == 20);
    CHECK(image_mean(none.image) == glm::dvec3(0.0));
}

TEST_CASE("render: the planted FlippedNormals defect turns one-sided lights away", "[render][defect]") {
    const Scene s = test::two_light_scene(16, 12);
    const DoublePrecisionAccel accel(s);
    RenderOptions o = options(8, 2);
    const double good = image_mean(render(s, accel, o).image).g;
    const double bad = image_mean(render_with_planted_defect(s, accel, o, PlantedDefect::FlippedNormals).image).g;
    // Both lights emit from their fronts only; with every normal inward the quad light shines up
    // (onto the wall above it only) and the sphere light into itself: the image goes nearly black.
    INFO("mean green: " << good << " -> " << bad);
    CHECK(good > 0.05);
    CHECK(bad < 0.05 * good);
}

TEST_CASE("render: invalid options are rejected", "[render]") {
    const Scene s = furnace_scene(glm::vec3(0.5f), glm::vec3(1.0f));
    const DoublePrecisionAccel accel(s);
    RenderOptions o = options(0);
    CHECK_THROWS_AS(render(s, accel, o), std::invalid_argument);
    o = options(1);
    o.max_depth = 0;
    CHECK_THROWS_AS(render(s, accel, o), std::invalid_argument);
    Scene empty = s;
    empty.film.width = 0;
    CHECK_THROWS_AS(render(empty, accel, options(1)), std::invalid_argument);
}

// A sky without a portal, found by next event estimation where path guiding learned where it is
// seen (render/guiding/sky_guide.hpp): the learned exits' and the defensive mixture's densities
// integrate to 1 over the sphere and are the ones their samples carry; LightSet makes the sky a light only with a guide, with the selection and
// MIS densities sample() and pdf() agree on; the guided render of the window room without its
// portal converges to BSDF sampling's image, with less noise than it at equal samples (guiding
// alone, on the main before this change, had more), and is the same bit for bit on 1 and 2
// threads.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "bidirectional_test_support.hpp"
#include "convergence_harness.hpp"
#include "raytracer/render/guiding/guiding_quadtree.hpp"
#include "raytracer/render/guiding/sky_guide.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/sampling.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;
using sweeptrace::testing::same_bits;

namespace {

constexpr int kDepth = 6;  // the test guide's deepest cells are 2^-6 wide on the square

// A guide that learned a window: most energy in a small patch of directions, the rest nowhere
// (cells with no energy, where only the mixture's uniform part reaches).
DirectionalQuadtree window_guide() {
    const glm::vec3 axis = glm::normalize(glm::vec3(-1.0f, 0.4f, 0.3f));
    Rng rng(3, 1, 4);
    DirectionalQuadtree tree;
    for (int iteration = 0; iteration < 3; ++iteration) {
        if (iteration > 0) tree = tree.refined(0.01, kDepth);
        for (int i = 0; i < 20000; ++i) {
            const glm::vec3 d = Frame(axis).to_world(uniform_cone(rng.uniform(), rng.uniform(), 0.05f));
            tree.record(d, 1.0f + rng.uniform());
        }
    }
    tree.freeze();
    return tree;
}

// Exits learned in a 4 x 3 x 5 room from rays through a window in its x = 0 wall (y 1..2.2,
// z 2..3.5), seen from points spread over the room.
SkyExitGuide window_exits() {
    SkyExitGuide exits;
    exits.start({0.0f, 0.0f, 0.0f}, {4.0f, 3.0f, 5.0f}, DirectionalQuadtree());
    Rng rng(4, 4, 4);
    for (int iteration = 0; iteration < 3; ++iteration) {
        if (iteration > 0) {
            exits.freeze();
            exits = exits.refined(0.01, 10);
        }
        for (int i = 0; i < 20000; ++i) {
            const glm::vec3 p(0.5f + 3.0f * rng.uniform(), 0.2f + 2.6f * rng.uniform(), 0.5f + 4.0f * rng.uniform());
            const glm::vec3 w(0.0f, 1.0f + 1.2f * rng.uniform(), 2.0f + 1.5f * rng.uniform());
            exits.record(p, glm::normalize(w - p), 1.0f);
        }
    }
    exits.freeze();
    return exits;
}

// The room of scenes/sky-window.json without its portal, tiny and depth 5.
Scene plain_sky_window() {
    Scene s = shipped("sky-window.json", 32, 24);
    s.background.has_portal = false;
    s.film.max_depth = 5;
    return s;
}

RenderOptions guided(int spp, std::uint64_t seed, int threads = 0) {
    RenderOptions o;
    o.spp = spp;
    o.max_depth = 5;
    o.seed = seed;
    o.threads = threads;
    o.guiding = true;
    return o;
}

}  // namespace

TEST_CASE("guided sky: the learned exits' density integrates to 1 over the sphere and aims at the window",
          "[render][guiding][sky]") {
    const SkyExitGuide exits = window_exits();
    REQUIRE(exits.total() > 0.0);
    Rng rng(6, 6, 6);
    for (const glm::vec3 p : {glm::vec3(2.0f, 1.0f, 2.5f), glm::vec3(3.5f, 0.3f, 4.5f), glm::vec3(0.4f, 2.7f, 0.6f)}) {
        REQUIRE(exits.covers(p));
        CHECK_FALSE(exits.covers(p + glm::vec3(10.0f, 0.0f, 0.0f)));
        // E over uniform directions of 4 pi pdf = the integral of the density = 1.
        double integral = 0.0;
        constexpr int kDirections = 400000;
        for (int i = 0; i < kDirections; ++i)
            integral += 4.0 * M_PI * double(exits.pdf(p, uniform_sphere(rng.uniform(), rng.uniform())));
        CHECK(integral / kDirections == Approx(1.0).epsilon(0.02));
        // Samples head for the window (its cells hold all the energy) and E[1 / pdf] over them is
        // the solid angle the learned exits cover, a small part of the sphere.
        int toward = 0;
        for (int i = 0; i < 2000; ++i) {
            glm::vec3 d;
            REQUIRE(exits.sample(p, rng.uniform(), rng.uniform(), d));
            REQUIRE(exits.pdf(p, d) > 0.0f);
            // Where the ray meets the x = 0 wall: in the window, but for cells astride its edge.
            const float t = -p.x / d.x;
            const glm::vec3 q = p + t * d;
            if (d.x < 0.0f && q.y > 0.9f && q.y < 2.3f && q.z > 1.9f && q.z < 3.6f) ++toward;
        }
        CHECK(toward > 1900);
    }
}

TEST_CASE("guided sky: the mixture's density integrates to 1 and is the density its samples carry", "[render][guiding][sky]") {
    const DirectionalQuadtree leaf = window_guide();
    const SkyExitGuide exits = window_exits();
    REQUIRE(leaf.depth() >= 4);
    const glm::vec3 p(2.0f, 1.0f, 2.5f);
    for (const SkyGuide guide : {SkyGuide{&leaf, nullptr}, SkyGuide{&leaf, &exits}}) {
        // Without the exits, exact: the leaf's density is constant on the finest cells of the
        // square, the uniform part constant everywhere. With them, by uniform directions.
        const int fine = 1 << kDepth;
        double sum = 0.0;
        for (int j = 0; j < fine; ++j)
            for (int i = 0; i < fine; ++i) {
                const glm::vec3 d = square_to_direction({(i + 0.5f) / fine, (j + 0.5f) / fine});
                sum += double(sky_mixture_density(guide, p, d)) * 4.0 * M_PI / (double(fine) * fine);
            }
        if (guide.exit == nullptr) CHECK(sum == Approx(1.0).epsilon(1e-5));
        Rng rng(8, 8, 8);
        double integral = 0.0;
        for (int i = 0; i < 400000; ++i)
            integral += 4.0 * M_PI * double(sky_mixture_density(guide, p, uniform_sphere(rng.uniform(), rng.uniform())));
        CHECK(integral / 400000.0 == Approx(1.0).epsilon(0.02));
        // Every sample carries the density sky_mixture_density states for it, whichever branch
        // drew it, and the uniform branch reaches directions nothing was learned about.
        int outside = 0;
        double mc = 0.0;  // E[1 / density] = 4 pi: the mixture covers the whole sphere
        constexpr int kSamples = 200000;
        for (int s = 0; s < kSamples; ++s) {
            float density = 0.0f;
            glm::vec3 d;
            REQUIRE(sample_sky_mixture(guide, p, {rng.uniform(), rng.uniform()}, d, density));
            REQUIRE(std::abs(glm::length(d) - 1.0f) < 1e-5f);
            REQUIRE(density == sky_mixture_density(guide, p, d));
            if (leaf.pdf(d) == 0.0f) ++outside;
            mc += 1.0 / double(density);
        }
        CHECK(outside > 0);
        CHECK(mc / kSamples == Approx(4.0 * M_PI).epsilon(0.03));
    }
}

TEST_CASE("guided sky: a light only with a guide, sampled and weighed with one density", "[render][guiding][sky]") {
    const Scene plain = plain_sky_window();
    const LightSet lights(plain);
    CHECK_FALSE(lights.background_is_light());  // for bdpt, vcm and unguided vertices: as before
    REQUIRE(lights.sky_is_guidable());
    CHECK(lights.sky_probability() == 1.0f);  // the only emitter
    const DirectionalQuadtree leaf = window_guide();
    const SkyExitGuide exits = window_exits();
    const SkyGuide guide{&leaf, &exits};
    const glm::vec3 p(2.0f, 1.0f, 2.5f);
    LightSample ls;
    CHECK_FALSE(lights.sample(p, LightSet::kNoObject, 0.3f, 0.5f, 0.2f, 0.7f, ls));  // no guide: no light
    Rng rng(2, 7, 1);
    for (int i = 0; i < 2000; ++i) {
        REQUIRE(lights.sample(p, LightSet::kNoObject, rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform(), ls,
                              nullptr, &guide));
        REQUIRE(ls.guided_sky);
        REQUIRE(ls.at_infinity);
        REQUIRE(ls.pdf == Approx(sky_mixture_density(guide, p, ls.wi)).epsilon(1e-4));
        // An escaped BSDF ray along the same direction takes the power heuristic against it.
        const float bsdf_pdf = 0.3f;
        REQUIRE(lights.guided_sky_weight(p, ls.wi, bsdf_pdf, &guide) == Approx(power_heuristic(bsdf_pdf, ls.pdf)).epsilon(1e-4));
    }
    CHECK(lights.guided_sky_weight(p, ls.wi, 0.3f, nullptr) == 1.0f);

    // Beside another light (the shipped default scene's bulb and sky): the sky takes its share
    // where guided, the bulb keeps the rest, and pdf() scales the bulb's density the same way.
    const Scene outdoor = shipped("default.json", 24, 14);
    const LightSet both(outdoor);
    REQUIRE(both.sky_is_guidable());
    const float ps = both.sky_probability();
    CHECK(ps > 0.0f);
    CHECK(ps < 1.0f);
    int sky = 0, other = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 q(0.1f * float(i % 7), 0.5f, 0.1f * float(i % 5));
        LightSample s;
        if (!both.sample(q, LightSet::kNoObject, rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform(), s, nullptr, &guide))
            continue;
        if (s.guided_sky) {
            ++sky;
            continue;
        }
        ++other;
        if (s.delta || s.at_infinity) continue;
        SurfaceHit h;  // where a BSDF ray along s.wi would have found the light
        h.point = s.point;
        h.normal = s.normal;
        for (std::uint32_t o = 0; o < outdoor.objects.size(); ++o)
            if (both.light_of_object(o) == s.light) h.object = o;
        REQUIRE(both.is_light(h.object));
        REQUIRE(both.pdf(q, LightSet::kNoObject, h, nullptr, &guide) ==
                Approx((1.0f - ps) * both.pdf(q, LightSet::kNoObject, h)).epsilon(1e-5));
        REQUIRE(s.pdf == Approx(both.pdf(q, LightSet::kNoObject, h, nullptr, &guide)).epsilon(1e-3));
    }
    const double share = double(sky) / double(sky + other);
    CHECK(share == Approx(ps).margin(0.03));
}

TEST_CASE("guided sky: the window room without its portal converges to BSDF sampling's image, less noisy",
          "[render][guiding][sky][convergence]") {
    const Scene plain = plain_sky_window();
    const auto accel = make_accel(AccelKind::Bvh, plain);
    const RenderResult reference =
        render_as(plain, *accel, IntegratorKind::Path, 1024, 1, PlantedDefect::None, 0, 0, Sampling::BsdfOnly);
    const RenderResult sky = render(plain, *accel, guided(64, 3));
    const BlockTestResult t = against_path(reference, sky, 4);
    INFO(t.summary());
    CHECK(t.pass());
    CHECK(sky.stats.nonfinite_samples == 0);
    // At equal samples: BSDF sampling's variance from its 1024 spp, scaled to 64. Measured with
    // the command line on the same room (32x24, depth 5, 64 spp, seed 3, --variance): 0.25x with
    // the sky guided; path guiding alone (the main before it) 1.14x, its first passes guided by
    // a guide learned from one or two.
    const double bsdf_64 = mean_pixel_variance(reference.variance) * (1024.0 / 64.0);
    const double v_sky = mean_pixel_variance(sky.variance);
    INFO("mean pixel variance at 64 spp: BSDF only " << bsdf_64 << ", guided sky " << v_sky);
    CHECK(v_sky < 0.5 * bsdf_64);
}

TEST_CASE("guided sky: the same bit for bit on 1 and 2 threads", "[render][guiding][sky]") {
    Scene plain = plain_sky_window();
    plain.film.width = 24;
    plain.film.height = 16;
    const auto accel = make_accel(AccelKind::Bvh, plain);
    const RenderResult one = render(plain, *accel, guided(8, 11, 1));  // guides of 1 and 2 passes used
    const RenderResult two = render(plain, *accel, guided(8, 11, 2));
    CHECK(same_bits(one.image, two.image));
    RenderOptions unguided = guided(8, 11, 2);
    unguided.guiding = false;
    CHECK_FALSE(same_bits(one.image, render(plain, *accel, unguided).image));
}

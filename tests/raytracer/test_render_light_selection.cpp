// Which light next event estimation picks (render/lights/lights.hpp, "Which light"): the lights at
// infinity share a fixed part, n / (n + 1), by their irradiance, the finite ones split the rest by
// power; the picks follow
// those probabilities (Pearson's chi-square), the density each sample reports is the one pdf() and
// the escaped-ray MIS weights use, a large scene no longer grows the sky's share, and NEE+MIS
// agrees with BSDF-only sampling on a scene lit by a quad, a sun and a map together.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

#include "bsdf_chi_square.hpp"
#include "convergence_harness.hpp"
#include "environment_test_maps.hpp"
#include "raytracer/render/lights/environment_light.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/sampling.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// Two quads (power 1 and 6, as in the power test of test_render_lights.cpp), a sun and a map.
Scene mixed_lights(bool far_wall) {
    Scene s = spheres_under(env_background(environment_test_map(32, 16), -40.0f, 0.5f), 32);
    Material dim, bright;
    dim.type = bright.type = Material::Type::Emissive;
    dim.emission = glm::vec3(1.0f);
    bright.emission = glm::vec3(3.0f);
    add_object(s, collision::Quad{{-1.0f, 3.0f, -1.0f}, {1, 0, 0}, {0, 0, 1}}, add_material(s, dim), glm::mat4(1.0f), "dim");
    add_object(s, collision::Quad{{0.5f, 3.0f, -1.0f}, {1, 0, 0}, {0, 0, 2}}, add_material(s, bright), glm::mat4(1.0f),
               "bright");
    SceneLight sun;
    sun.type = SceneLight::Type::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
    sun.irradiance = glm::vec3(2.0f);
    sun.half_angle = 0.2f;
    sun.name = "sun";
    s.lights.push_back(sun);
    // A wall far away: under the old rule (power E pi R^2 for lights at infinity) it raised the
    // sun's and the map's shares with the scene's radius.
    if (far_wall)
        add_object(s, collision::Quad{{-500.0f, 0.0f, -500.0f}, {1000.0f, 0.0f, 0.0f}, {0.0f, 1000.0f, 0.0f}},
                   add_material(s, diffuse(0.5f)), glm::mat4(1.0f), "far wall");
    return s;
}

}  // namespace

TEST_CASE("light selection: lights at infinity share a fixed part by irradiance, finite lights the rest by power, and picks follow it",
          "[render][lights]") {
    for (const bool far_wall : {false, true}) {
        INFO("far wall " << far_wall);
        const Scene scene = mixed_lights(far_wall);
        const LightSet lights(scene);
        REQUIRE(lights.light_count() == 4);  // dim, bright, sun, environment
        const std::uint32_t dim = 3, bright = 4;
        REQUIRE(lights.light_name(lights.light_of_object(dim)) == "dim");
        REQUIRE(lights.light_name(2) == "sun");
        REQUIRE(lights.light_name(3) == "environment");
        // Two lights at infinity and a finite group: 2/3 split as the sun's E (2) to the map's
        // largest irradiance on a disc; the quads split 1/3 as 1 : 6.
        const EnvironmentLight env(scene.background);
        const double e_env = env.max_irradiance();
        const std::vector<double> expected{1.0 / 21.0, 6.0 / 21.0, 2.0 / 3.0 * 2.0 / (2.0 + e_env),
                                           2.0 / 3.0 * e_env / (2.0 + e_env)};
        CHECK(lights.selection_probability(dim) == Approx(expected[0]));
        CHECK(lights.selection_probability(bright) == Approx(expected[1]));

        Rng rng(7, far_wall ? 1 : 0, 0);
        constexpr int n = 40000;
        std::vector<double> counts(4, 0.0);
        const glm::vec3 p(0.0f, 0.5f, 1.0f);
        for (int i = 0; i < n; ++i) {
            LightSample ls;
            const bool ok =
                lights.sample(p, LightSet::kNoObject, rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform(), ls);
            REQUIRE(ls.light >= 0);
            REQUIRE(ls.light < 4);
            counts[static_cast<std::size_t>(ls.light)] += 1.0;
            if (!ok) continue;
            // The density each strategy reports includes exactly this selection probability.
            if (ls.light == 3) {
                REQUIRE(ls.pdf == Approx(expected[3] * env.pdf(ls.wi)).epsilon(1e-4));
            } else if (ls.light == 2) {
                const float omc = 1.0f - std::cos(0.2f);
                REQUIRE(ls.pdf == Approx(expected[2] * uniform_cone_pdf(omc)).epsilon(1e-3));
                // A BSDF-sampled ray that escapes along ls.wi with the same density: the sun's
                // MIS weight is 1/2 only if escaped_radiance uses that same selection probability;
                // the map's, lit behind it, by its own.
                const double b = ls.pdf, p_env = expected[3] * env.pdf(ls.wi);
                const double want = 0.5 * luminance(ls.radiance) + luminance(env.radiance(ls.wi)) * b * b / (b * b + p_env * p_env);
                REQUIRE(luminance(lights.escaped_radiance(p, ls.wi, ls.pdf)) == Approx(want).epsilon(1e-3));
            } else {
                SurfaceHit h;
                h.object = ls.light == 0 ? dim : bright;
                h.point = ls.point;
                h.normal = ls.normal;
                REQUIRE(ls.pdf == Approx(lights.pdf(p, LightSet::kNoObject, h)).epsilon(1e-4));
            }
        }
        double chi2 = 0.0;
        for (std::size_t k = 0; k < 4; ++k) {
            const double e = n * expected[k];
            chi2 += (counts[k] - e) * (counts[k] - e) / e;
        }
        const double p_value = sweeptrace::test::gamma_q(1.5, chi2 / 2.0);  // 3 degrees of freedom
        INFO("chi2 " << chi2 << " p " << p_value);
        CHECK(p_value > 1e-3);
    }
}

TEST_CASE("light selection: with only lights at infinity they split all of it by irradiance, and a delta sun reports its selection probability",
          "[render][lights]") {
    Scene only_far = spheres_under(env_background(environment_test_map(32, 16), -40.0f, 0.5f), 8);
    SceneLight sun;
    sun.type = SceneLight::Type::Directional;
    sun.irradiance = glm::vec3(5.0f);
    only_far.lights.push_back(sun);
    const LightSet a(only_far);
    const double e_env = EnvironmentLight(only_far.background).max_irradiance();
    const double p_sun = 5.0 / (5.0 + e_env);
    Rng rng(3, 0, 0);
    int picked_sun = 0;
    constexpr int n = 20000;
    for (int i = 0; i < n; ++i) {
        LightSample ls;
        a.sample({0.0f, 0.5f, 1.0f}, LightSet::kNoObject, rng.uniform(), 0.5f, rng.uniform(), rng.uniform(), ls);
        picked_sun += ls.light == 0 ? 1 : 0;
        if (ls.light == 0) REQUIRE(ls.pdf == Approx(p_sun));  // a delta direction: pdf = selection probability
    }
    CHECK(std::abs(picked_sun - n * p_sun) < 4.0 * std::sqrt(n * p_sun * (1.0 - p_sun)));
}

TEST_CASE("light selection: a map's weight is its largest irradiance on a disc, as a sun's is its E", "[render][lights]") {
    // Exact values: a uniform map of luminance 1 gives pi to a disc facing any way (a quarter of
    // its int L d omega = 4 pi); the upper half alone gives pi to a disc facing up; one bright
    // texel gives its lum d omega to a disc facing it (the order-2 harmonics: 1.06x, at an
    // orientation within a few degrees of it).
    using Mapping = Background::EnvironmentMapping;
    const double kTestPi = 3.14159265358979323846;
    for (const Mapping mapping : {Mapping::Equirect, Mapping::EqualArea}) {
        const bool equal_area = mapping == Mapping::EqualArea;
        INFO("equal-area " << equal_area);
        const int w = 64, h = equal_area ? 64 : 32;
        auto uniform = std::make_shared<Image>(w, h), upper = std::make_shared<Image>(w, h), texel = std::make_shared<Image>(w, h);
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) {
                uniform->at(i, j) = glm::vec3(1.0f);
                texel->at(i, j) = glm::vec3(0.0f);
            }
        texel->at(w / 3, h / 5) = glm::vec3(500.0f);
        // (EnvironmentLight keeps a pointer to its Background: each is a named variable.)
        const Background uniform_bg = env_background(uniform, 30.0f, 1.0f, mapping);
        const EnvironmentLight u(uniform_bg);
        CHECK(u.luminance_integral() == Approx(4.0 * kTestPi).epsilon(2e-3));
        CHECK(u.max_irradiance() == Approx(kTestPi).epsilon(2e-3));
        const Background texel_bg = env_background(texel, 0.0f, 1.0f, mapping);
        const EnvironmentLight t(texel_bg);
        CHECK(t.max_irradiance() / t.luminance_integral() > 0.97);
        CHECK(t.max_irradiance() / t.luminance_integral() < 1.07);
        if (!equal_area) {
            // The upper half (rows above the equirect map's equator, y > 0): pi to a disc facing up.
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) upper->at(i, j) = glm::vec3(j < h / 2 ? 1.0f : 0.0f);
            const Background upper_bg = env_background(upper, 0.0f, 1.0f, mapping);
            const EnvironmentLight half(upper_bg);
            CHECK(half.max_irradiance() == Approx(kTestPi).epsilon(1e-2));
        }
    }
}

TEST_CASE("light selection: NEE+MIS and BSDF-only agree under a quad, a sun and a map together", "[render][lights][mis]") {
    // The BSDF-only render finds the sun's 0.2 rad disc and the bright texel in few paths, so it
    // runs 4x the samples (as the environment's MIS test does).
    const Scene scene = mixed_lights(false);
    const RenderResult mis = render_with(scene, AccelKind::Bvh, 64, 4, 41, Sampling::NeeMis);
    const RenderResult bsdf = render_with(scene, AccelKind::Bvh, 256, 4, 42, Sampling::BsdfOnly);
    const BlockTestResult t = renders_agree(mis, bsdf);
    INFO(t.summary());
    CHECK(t.pass());
}

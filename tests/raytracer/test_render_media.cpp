// Participating media (render/media/): the closed forms of issue 41's first "Done when" item.
//   - transmittance through a homogeneous slab is exp(-sigma_t d) by delta and by ratio tracking;
//   - ratio tracking through a linear density ramp (a grid, its majorant grid walked by the DDA)
//     matches the analytic exp(-integral);
//   - Henyey-Greenstein sampling passes a chi-square test against its density for several g;
//   - a white furnace: an albedo-1 (chromatic, anisotropic) medium inside a uniformly emitting
//     closed sphere gives the emitter's radiance at every pixel;
//   - single scattering of a point light in a homogeneous medium at a pixel agrees with a
//     numerical quadrature of the same integral;
//   - a grid of constant density renders the same as the homogeneous medium (z-test).
// Besides: bit-identical at 1 and 3 threads, the BVH and Embree agree, bdpt and vcm refuse.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "bsdf_chi_square.hpp"
#include "convergence_harness.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/media/henyey_greenstein.hpp"
#include "raytracer/render/media/tracking.hpp"
#include "medium_test_scenes.hpp"
#include "render_test_stats.hpp"

using namespace sweeptrace;
using sweeptrace::test::Estimate;
using sweeptrace::test::blocks_apart;
using sweeptrace::test::medium_ball_scene;
using sweeptrace::test::z_bound;

namespace {

Medium homogeneous_medium(const glm::vec3& sigma_a, const glm::vec3& sigma_s, float g = 0.0f) {
    Medium m;
    m.sigma_a = sigma_a;
    m.sigma_s = sigma_s;
    m.g = g;
    return m;
}

// The z of an estimate against the truth, per channel.
void check_channels(const Estimate (&e)[3], const glm::dvec3& truth, int tests) {
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c << ": estimate " << e[c].mean << " +- " << e[c].standard_error() << ", truth " << truth[c]);
        CHECK(std::abs(e[c].mean - truth[c]) <= z_bound(tests) * e[c].standard_error() + 1e-6 * truth[c]);
    }
}

}  // namespace

TEST_CASE("media: transmittance through a homogeneous slab is exp(-sigma_t d) by delta and ratio tracking", "[media]") {
    // Chromatic and absorbing only, so a path that passes carries exactly the transmittance.
    const Medium m = homogeneous_medium({0.3f, 0.9f, 2.0f}, glm::vec3(0.0f));
    const MediumModel model(m);
    const float d = 1.3f;
    const glm::dvec3 truth(std::exp(-0.3 * d), std::exp(-0.9 * d), std::exp(-2.0 * d));
    const glm::vec3 o(0.0f), dir(0.0f, 0.0f, 1.0f);
    Estimate delta[3], ratio[3];
    Rng rng(41, 0, 0);
    for (int i = 0; i < 100000; ++i) {
        // Delta tracking: a hero channel per path, spectral MIS (tracking.hpp).
        const int hero = std::min(2, static_cast<int>(rng.uniform() * 3.0f));
        glm::vec3 beta(1.0f), r_u(1.0f);
        const FlightResult f = delta_track(model, o, dir, 0.0f, d, hero, rng, beta, r_u, false);
        const glm::vec3 passed = f.event == Flight::Passed ? beta : glm::vec3(0.0f);
        const glm::vec3 tr = ratio_track(model, o, dir, 0.0f, d, rng);
        for (int c = 0; c < 3; ++c) {
            delta[c].add(passed[c]);
            ratio[c].add(tr[c]);
        }
    }
    check_channels(delta, truth, 6);
    check_channels(ratio, truth, 6);
    // The closed form the integrators use for homogeneous media.
    const glm::vec3 exact = transmittance(model, o, dir, 0.0f, d, rng);
    for (int c = 0; c < 3; ++c) CHECK(exact[c] == Approx(truth[c]).epsilon(1e-6));
}

TEST_CASE("media: ratio tracking through a linear density ramp matches its analytic transmittance", "[media]") {
    // 8 samples along x, density 1..8; along y and z one sample, read exactly at y = z = 0.5.
    // Between the first and the last voxel centre the trilinear density is exactly linear.
    Medium m;
    m.kind = Medium::Kind::Grid;
    m.sigma_a = glm::vec3(0.2f, 0.4f, 0.6f);
    m.sigma_s = glm::vec3(0.1f);
    m.nx = 8;
    m.ny = m.nz = 1;
    for (int i = 0; i < 8; ++i) m.density.push_back(static_cast<float>(i + 1));
    m.p0 = glm::vec3(0.0f);
    m.p1 = glm::vec3(2.0f, 1.0f, 1.0f);  // x over [0, 2]: voxel centres at 0.125 ... 1.875
    // The medium moved by its own transform: world = medium + (5, 0, 0).
    m.to_medium = glm::translate(glm::mat4(1.0f), glm::vec3(-5.0f, 0.0f, 0.0f));
    const MediumModel model(m);
    const float t0 = 0.125f, t1 = 1.875f;
    const double integral = 0.5 * (1.0 + 8.0) * (t1 - t0);  // of the density over [t0, t1]
    const glm::dvec3 st(0.3, 0.5, 0.7);
    const glm::dvec3 truth(std::exp(-st.x * integral), std::exp(-st.y * integral), std::exp(-st.z * integral));
    const glm::vec3 o(5.0f, 0.5f, 0.5f), dir(1.0f, 0.0f, 0.0f);
    Estimate ratio[3];
    Rng rng(42, 0, 0);
    std::uint64_t fine = 0, global = 0;
    const MediumModel one_bound(m, 1);  // a single majorant for the whole grid
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 tr = ratio_track(model, o, dir, t0, t1, rng, &fine);
        for (int c = 0; c < 3; ++c) ratio[c].add(tr[c]);
        ratio_track(one_bound, o, dir, t0, t1, rng, &global);
    }
    check_channels(ratio, truth, 3);
    // The finer bound takes fewer tentative collisions on a ramp (the mean density is 4.5 of 8).
    CHECK(fine < global);
}

TEST_CASE("media: the majorant grid bounds every density lookup in its cells", "[media]") {
    Medium m;
    m.kind = Medium::Kind::Grid;
    m.nx = 5;
    m.ny = 3;
    m.nz = 7;
    Rng rng(43, 0, 0);
    for (int i = 0; i < 5 * 3 * 7; ++i) m.density.push_back(rng.uniform() < 0.5f ? 0.0f : 10.0f * rng.uniform());
    m.sigma_s = glm::vec3(1.0f);
    const MediumModel model(m, 4);
    int below = 0, checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 o(rng.uniform(), rng.uniform(), rng.uniform());
        const glm::vec3 d = glm::normalize(glm::vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
        model.majorants(o, d, -2.0f, 2.0f, [&](float a, float b, float mu) {
            const float t = a + (b - a) * rng.uniform();
            ++checked;
            below += model.at(o + t * d).sigma_s.x <= mu * (1.0f + 1e-5f);
            return true;
        });
    }
    CHECK(checked > 20000);
    CHECK(below == checked);
}

TEST_CASE("media: Henyey-Greenstein sampling passes a chi-square test against its density", "[media]") {
    const glm::vec3 forward = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
    const Frame frame(forward);
    const std::vector<float> gs = {-0.8f, -0.3f, 0.0f, 1e-4f, 0.5f, 0.95f};
    for (const float g : gs) {
        // Bins: 40 in cos_theta by 16 in phi; each bin's probability from the closed-form CDF in
        // cos_theta (p's integral over the sphere, 2 pi times that over cos_theta).
        constexpr int n_mu = 40, n_phi = 16, samples = 200000;
        const auto cdf = [&](double mu) {
            if (g == 0.0f) return 0.5 * (mu + 1.0);
            const double gd = g;
            return (1.0 - gd * gd) / (2.0 * gd) * (1.0 / std::sqrt(1.0 + gd * gd - 2.0 * gd * mu) - 1.0 / (1.0 + gd));
        };
        std::vector<double> observed(n_mu * n_phi, 0.0), expected(n_mu * n_phi, 0.0);
        Rng rng(44, static_cast<std::uint64_t>(g * 1000.0f + 1000.0f), 0);
        int pdf_mismatch = 0;
        for (int i = 0; i < samples; ++i) {
            float pdf = 0.0f;
            const glm::vec3 wi = hg_sample(forward, g, rng.uniform(), rng.uniform(), pdf);
            const glm::vec3 l = frame.to_local(wi);
            pdf_mismatch += std::abs(pdf - hg_phase(glm::dot(forward, wi), g)) > 1e-3f * pdf;
            const double mu = std::clamp(static_cast<double>(l.z), -1.0, 1.0);
            double phi = std::atan2(static_cast<double>(l.y), static_cast<double>(l.x));
            if (phi < 0.0) phi += 2.0 * M_PI;
            const int im = std::min(n_mu - 1, static_cast<int>((mu + 1.0) / 2.0 * n_mu));
            const int ip = std::min(n_phi - 1, static_cast<int>(phi / (2.0 * M_PI) * n_phi));
            observed[static_cast<std::size_t>(im * n_phi + ip)] += 1.0;
        }
        for (int im = 0; im < n_mu; ++im)
            for (int ip = 0; ip < n_phi; ++ip)
                expected[static_cast<std::size_t>(im * n_phi + ip)] =
                    samples * (cdf(-1.0 + 2.0 * (im + 1) / n_mu) - cdf(-1.0 + 2.0 * im / n_mu)) / n_phi;
        // Bins expected below 5 pooled into one.
        double stat = 0.0, pool_o = 0.0, pool_e = 0.0;
        int bins = 0;
        for (std::size_t k = 0; k < expected.size(); ++k) {
            if (expected[k] < 5.0) {
                pool_o += observed[k];
                pool_e += expected[k];
                continue;
            }
            stat += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
            ++bins;
        }
        if (pool_e > 0.0) {
            stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
            ++bins;
        }
        const double p = sweeptrace::test::gamma_q(0.5 * (bins - 1), 0.5 * stat);
        INFO("g " << g << ": chi2 " << stat << " over " << bins << " bins, p " << p);
        CHECK(p > sweeptrace::test::chi_square_alpha(static_cast<int>(gs.size())));
        CHECK(pdf_mismatch == 0);
    }
}

namespace {

using sweeptrace::testing::add_object;
using sweeptrace::testing::empty_scene;

// The camera at the centre of an emitting sphere of radius 1 filled with `m`.
Scene furnace_scene(const Medium& m, const glm::vec3& le) {
    Scene scene = empty_scene(8, 8);
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.look_at = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.vfov_degrees = 90.0f;
    scene.camera.medium = 0;
    scene.media.push_back(m);
    Material wall;
    wall.type = Material::Type::Emissive;
    wall.albedo = glm::vec3(0.0f);
    wall.emission = le;
    wall.two_sided_emission = true;
    add_object(scene, collision::Sphere{glm::vec3(0.0f), 1.0f}, sweeptrace::test::add_material(scene, wall),
               glm::mat4(1.0f), "wall");
    return scene;
}

// Per channel: every pixel within its noise of `truth` (a z-test per pixel and channel).
int pixels_off(const RenderResult& r, const glm::vec3& truth) {
    const int n = r.image.width * r.image.height * 3;
    int off = 0;
    for (int y = 0; y < r.image.height; ++y)
        for (int x = 0; x < r.image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double e = r.image.at(x, y)[c], se = std::sqrt(static_cast<double>(r.variance.at(x, y)[c]));
                off += std::abs(e - truth[c]) > z_bound(n) * se + 1e-5 * truth[c];
            }
    return off;
}

}  // namespace

TEST_CASE("media: a white furnace: an albedo-1 medium inside an emitting sphere shows the emitter's radiance",
          "[media]") {
    const glm::vec3 le(0.5f, 1.0f, 2.0f);
    // Chromatic (spectral MIS) and forward scattering (phase sampling against light sampling).
    const Scene scene = furnace_scene(homogeneous_medium(glm::vec3(0.0f), {0.5f, 1.0f, 2.0f}, 0.6f), le);
    const RenderResult r = sweeptrace::testing::render_with(scene, AccelKind::Bvh, 256, 64, 7);
    INFO("pixel (3, 3): " << r.image.at(3, 3).x << " " << r.image.at(3, 3).y << " " << r.image.at(3, 3).z);
    CHECK(pixels_off(r, le) == 0);
    // Not vacuously: the noise is there (the medium scatters), and an absorbing medium is darker.
    CHECK(r.variance.at(3, 3).y > 0.0f);
    const Scene dark = furnace_scene(homogeneous_medium(glm::vec3(0.5f), {0.5f, 1.0f, 2.0f}, 0.6f), le);
    const RenderResult d = sweeptrace::testing::render_with(dark, AccelKind::Bvh, 64, 64, 7);
    CHECK(d.image.at(3, 3).y < 0.8f * le.y);
}

namespace {

// The camera in an unbounded homogeneous medium with a point light off its axis; 1 x 1 pixel of a
// tiny field of view, so the pixel is the radiance along one ray.
Scene single_scatter_scene(const Medium& m, const glm::vec3& light, const glm::vec3& intensity) {
    Scene scene = empty_scene(1, 1);
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.look_at = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.vfov_degrees = 1e-3f;
    scene.camera.medium = 0;
    scene.media.push_back(m);
    SceneLight l;
    l.type = SceneLight::Type::Point;
    l.position = light;
    l.intensity = intensity;
    scene.lights.push_back(l);
    return scene;
}

}  // namespace

TEST_CASE("media: single scattering of a point light agrees with a numerical quadrature", "[media]") {
    const glm::dvec3 sa(0.05, 0.1, 0.2), ss(0.3, 0.5, 0.4);
    const double g = 0.4;
    const glm::dvec3 light(0.3, 0.5, -2.0), intensity(3.0, 2.0, 1.0);
    const Scene scene = single_scatter_scene(homogeneous_medium(glm::vec3(sa), glm::vec3(ss), static_cast<float>(g)),
                                             glm::vec3(light), glm::vec3(intensity));
    // max_depth 2: the camera ray's one scattering vertex and its light sample, nothing more.
    const RenderResult r = sweeptrace::testing::render_with(scene, AccelKind::Bvh, 40000, 2, 11);
    // L = integral over t of T(t) sigma_s p(cos) I T(d) / d^2 along the ray (0, 0, -t), by
    // Simpson's rule on t in [0, 200] (the rest is below exp(-70)) with 200000 intervals.
    glm::dvec3 truth(0.0);
    const int n = 200000;
    const double t_max = 200.0, h = t_max / n;
    for (int i = 0; i <= n; ++i) {
        const double t = i * h;
        const glm::dvec3 p(0.0, 0.0, -t);
        const glm::dvec3 to = light - p;
        const double d = glm::length(to);
        const double cos_theta = glm::dot(glm::dvec3(0.0, 0.0, -1.0), to / d);
        const double phase = (1.0 - g * g) / (4.0 * M_PI * std::pow(1.0 + g * g - 2.0 * g * cos_theta, 1.5));
        const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        for (int c = 0; c < 3; ++c) {
            const double st = sa[c] + ss[c];
            truth[c] += w * h / 3.0 * std::exp(-st * t) * ss[c] * phase * intensity[c] * std::exp(-st * d) / (d * d);
        }
    }
    for (int c = 0; c < 3; ++c) {
        const double e = r.image.at(0, 0)[c], se = std::sqrt(static_cast<double>(r.variance.at(0, 0)[c]));
        INFO("channel " << c << ": render " << e << " +- " << se << ", quadrature " << truth[c]);
        CHECK(std::abs(e - truth[c]) <= z_bound(3) * se + 1e-5 * truth[c]);
        CHECK(se < 0.05 * truth[c]);  // a test with teeth: the noise is small against the value
    }
}

namespace {

Medium constant_grid(const Medium& h, float density) {
    Medium m = h;
    m.kind = Medium::Kind::Grid;
    m.nx = m.ny = m.nz = 4;
    m.density.assign(64, density);
    // The box reaches half a voxel (0.5) past the ball, so the density is constant in it
    // (it fades to 0 only in the outer half voxel of the grid, as pbrt-v4's lookup does).
    m.p0 = glm::vec3(-2.0f);
    m.p1 = glm::vec3(2.0f);
    m.sigma_a = h.sigma_a / density;
    m.sigma_s = h.sigma_s / density;
    return m;
}

}  // namespace

TEST_CASE("media: a grid of constant density renders as the homogeneous medium", "[media]") {
    const Medium h = homogeneous_medium({0.1f, 0.2f, 0.4f}, {1.2f, 0.9f, 0.6f}, 0.3f);
    const RenderResult a = sweeptrace::testing::render_with(medium_ball_scene(h), AccelKind::Bvh, 96, 8, 3);
    const RenderResult b = sweeptrace::testing::render_with(medium_ball_scene(constant_grid(h, 2.0f)), AccelKind::Bvh, 96, 8, 4);
    CHECK(blocks_apart(a, b) == 0);
    // And the test can fail: a grid twice as dense is told apart.
    Medium denser = constant_grid(h, 2.0f);
    denser.sigma_s *= 2.0f;
    const RenderResult c = sweeptrace::testing::render_with(medium_ball_scene(denser), AccelKind::Bvh, 96, 8, 5);
    CHECK(blocks_apart(a, c) > 0);
}

TEST_CASE("media: the BVH and Embree agree on a medium scene, and any thread count gives the same image", "[media]") {
    const Scene scene = medium_ball_scene(homogeneous_medium({0.1f, 0.2f, 0.4f}, {1.2f, 0.9f, 0.6f}, 0.3f));
    const RenderResult bvh = sweeptrace::testing::render_with(scene, AccelKind::Bvh, 64, 8, 3);
    const RenderResult embree = sweeptrace::testing::render_with(scene, AccelKind::Embree, 64, 8, 4);
    CHECK(blocks_apart(bvh, embree) == 0);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const auto runs = sweeptrace::testing::render_on_1_and_3_threads(scene, *accel);
    CHECK(sweeptrace::testing::same_bits(runs.one.image, runs.three.image));
}

TEST_CASE("media: bdpt and vcm refuse a scene with media instead of rendering it wrong", "[media]") {
    const Scene scene = medium_ball_scene(homogeneous_medium(glm::vec3(0.1f), glm::vec3(1.0f)));
    const auto accel = make_accel(AccelKind::Bvh, scene);
    for (const IntegratorKind k : {IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        RenderOptions o;
        o.spp = 1;
        o.integrator = k;
        CHECK_THROWS_WITH(render(scene, *accel, o), Catch::Contains("does not render participating media yet"));
    }
    RenderOptions o;
    o.spp = 1;
    CHECK_NOTHROW(render(scene, *accel, o));
}

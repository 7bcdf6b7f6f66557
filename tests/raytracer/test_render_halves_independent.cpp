// The half buffers of render --aovs as NFOR's error estimate takes them: independent estimates
// of the pixel. On a region of one true value (a diffuse floor under a sky, whose radiance is the
// same at every point of it), independent halves e and o have E(e - o)^2 = E(e - m)^2 + E(o - m)^2,
// so the ratio of those sums over the region is 1 within its noise. Under the sobol-halves sampler
// (render/sampling/sampler.hpp) it is; under the plain Sobol sampler, whose even and odd samples are one
// stratified sequence, the halves' errors are anti-correlated and the ratio is well above 1; the
// independent sampler is the control that the statistic itself is right.
#include <cmath>
#include <cstddef>

#include <catch2/catch.hpp>

#include "convergence_harness.hpp"
#include "raytracer/image/feature_sums.hpp"
#include "raytracer/render/renderer.hpp"
#include "render_test_scenes.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

constexpr int kWidth = 32, kHeight = 24;

// The camera looks down at a floor that fills the image and reaches far past it on every side, so
// every pixel sees the same radiance: the floor's albedo times the sky's irradiance over pi.
Scene sky_floor_scene() {
    Scene scene = empty_scene(kWidth, kHeight);
    scene.camera.position = {0.0f, 2.0f, 0.0f};
    scene.camera.look_at = {0.0f, 0.0f, -1.0f};
    scene.camera.vfov_degrees = 40.0f;
    scene.background.kind = Background::Kind::Sky;
    scene.background.horizon = {1.0f, 0.9f, 0.8f};
    scene.background.zenith = {0.1f, 0.3f, 1.0f};
    test::add_object(scene, collision::Quad{{-200.0f, 0.0f, 200.0f}, {400.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -400.0f}},
               add_material(scene, diffuse(0.5f)));
    return scene;
}

// sum (e - o)^2 / sum ((e - m)^2 + (o - m)^2) over the pixels and channels, m the image's mean
// per channel.
double halves_ratio(SamplerKind sampler) {
    const Scene scene = sky_floor_scene();
    const test::DoublePrecisionAccel accel(scene);
    RenderOptions o;
    o.spp = 32;
    o.max_depth = 2;
    o.seed = 7;
    o.sampler = sampler;
    o.aovs = true;
    const RenderResult r = render(scene, accel, o);
    const FeatureLayers L = feature_layers(r.features, kWidth, kHeight);
    double mean[3] = {0.0, 0.0, 0.0};
    for (const glm::vec3& p : L.color.pixels)
        for (int c = 0; c < 3; ++c) mean[c] += p[c] / double(L.color.pixels.size());
    double diff = 0.0, apart = 0.0;
    for (std::size_t i = 0; i < L.color.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double e = L.half_color[0].pixels[i][c], od = L.half_color[1].pixels[i][c];
            diff += (e - od) * (e - od);
            apart += (e - mean[c]) * (e - mean[c]) + (od - mean[c]) * (od - mean[c]);
        }
    REQUIRE(apart > 0.0);  // there is noise to compare
    return diff / apart;
}

}  // namespace

TEST_CASE("sobol-halves: the even and odd half buffers are independent, plain Sobol's are not", "[render][aovs][sampler]") {
    // 768 pixels: the ratio's standard deviation is about sqrt(2 / 768) = 0.05 for independent
    // halves (less: the channels share most of their noise, and count as fewer samples still).
    const double independent = halves_ratio(SamplerKind::Independent);
    const double halves = halves_ratio(SamplerKind::SobolHalves);
    const double sobol = halves_ratio(SamplerKind::Sobol);
    INFO("independent " << independent << ", sobol-halves " << halves << ", sobol " << sobol);
    CHECK(std::abs(independent - 1.0) < 0.2);
    CHECK(std::abs(halves - 1.0) < 0.2);
    CHECK(sobol > 1.4);
}

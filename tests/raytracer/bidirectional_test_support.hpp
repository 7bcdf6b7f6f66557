#pragma once
// What the bidirectional methods' tests share (test_render_bdpt.cpp, test_render_vcm.cpp): a
// shipped scene at a test size, a render by a chosen integrator, the block z-test of one noisy
// render against another, and the determinism check.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "convergence_harness.hpp"
#include "raytracer/render/planted_defect.hpp"
#include "raytracer/scene/load_scene.hpp"

namespace sweeptrace::testing {

inline Scene shipped(const char* name, int width, int height) {
    Scene s = load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / name);
    s.film.width = width;
    s.film.height = height;
    // The path tracer's firefly guard is biased on purpose and bdpt and vcm do not apply it: all
    // estimate the unclamped image here.
    s.film.clamp_indirect = 0.0f;
    return s;
}

inline RenderResult render_as(const Scene& scene, const Accel& accel, IntegratorKind integrator, int spp,
                              std::uint64_t seed, PlantedDefect defect = PlantedDefect::None, int threads = 0,
                              int first_sample = 0, Sampling sampling = Sampling::NeeMis,
                              SamplerKind sampler = SamplerKind::Sobol) {
    RenderOptions o;
    o.integrator = integrator;
    o.sampler = sampler;
    o.spp = spp;
    o.first_sample = first_sample;
    o.max_depth = scene.film.max_depth;
    o.seed = seed;
    o.threads = threads;
    o.sampling = sampling;
    return render_with_planted_defect(scene, accel, o, defect);
}

// A render against an independent one (the path tracer's, or bdpt's where the path tracer cannot
// converge): both noisy, so the null variance is the reference's and its noise is counted as
// large again (2 max(Va, Vb) >= Va + Vb).
inline BlockTestResult against_path(const RenderResult& path, const RenderResult& r, int block) {
    BlockTestOptions options;
    options.block = block;
    options.golden_is_8bit = false;
    options.reference_noise_ratio = 1.0;
    options.null_variance = &path.variance;
    return block_test(path.image, r.image, r.variance, options);
}

// `integrator` at `spp` (seed 2) against the path tracer at `path_spp` (seed 1), block z-test: it
// must pass.
inline void check_agrees_with_path(const Scene& scene, const Accel& accel, IntegratorKind integrator, int path_spp,
                                   int spp, int block, SamplerKind sampler = SamplerKind::Sobol) {
    const RenderResult path = render_as(scene, accel, IntegratorKind::Path, path_spp, 1);
    const RenderResult r = render_as(scene, accel, integrator, spp, 2, PlantedDefect::None, 0, 0, Sampling::NeeMis, sampler);
    const BlockTestResult t = against_path(path, r, block);
    INFO(t.summary());
    CHECK(t.pass());
    CHECK(r.stats.nonfinite_samples == 0);
}

// bdpt and vcm at `spp` (seed 2) each against one path tracer render at `path_spp` (seed 1).
inline void check_bidirectional_agree_with_path(const Scene& scene, const Accel& accel, int path_spp, int spp, int block) {
    const RenderResult path = render_as(scene, accel, IntegratorKind::Path, path_spp, 1);
    for (const IntegratorKind method : {IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        INFO((method == IntegratorKind::Vcm ? "vcm" : "bdpt"));
        const RenderResult r = render_as(scene, accel, method, spp, 2);
        const BlockTestResult t = against_path(path, r, block);
        INFO(t.summary());
        CHECK(t.pass());
        CHECK(r.stats.nonfinite_samples == 0);
    }
}

// default.json at 24x14, depth 5, with every kind of light at once: its sphere, a point, a spot,
// a sun (the determinism tests').
inline Scene every_light_scene() {
    Scene scene = shipped("default.json", 24, 14);
    SceneLight point;
    point.type = SceneLight::Type::Point;
    point.position = {1.0f, 2.0f, 2.0f};
    point.intensity = glm::vec3(3.0f);
    SceneLight spot = point;
    spot.type = SceneLight::Type::Spot;
    spot.direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.5f));
    spot.cos_cone = std::cos(0.5f);
    spot.cos_falloff_start = std::cos(0.3f);
    SceneLight sun;
    sun.type = SceneLight::Type::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
    sun.irradiance = glm::vec3(1.0f);
    sun.half_angle = 0.05f;
    scene.lights = {point, spot, sun};
    scene.film.max_depth = 5;
    return scene;
}

// 3 samples (seed 9) of `integrator`: the same sums on 1, 2 and 3 threads, and a farm split
// [0, 1) + [1, 3) sums to them; returns the 1-thread render.
inline RenderResult check_bit_identical(const Scene& scene, const Accel& accel, IntegratorKind integrator) {
    RenderResult one = render_as(scene, accel, integrator, 3, 9, PlantedDefect::None, 1);
    for (const int threads : {2, 3}) {
        const RenderResult other = render_as(scene, accel, integrator, 3, 9, PlantedDefect::None, threads);
        INFO(threads << " threads");
        CHECK(same_bits(one.image, other.image));
        CHECK(one.sums == other.sums);
    }
    const RenderResult a = render_as(scene, accel, integrator, 1, 9, PlantedDefect::None, 2, 0);
    const RenderResult b = render_as(scene, accel, integrator, 2, 9, PlantedDefect::None, 2, 1);
    std::vector<PixelSum> merged = a.sums;
    for (std::size_t i = 0; i < merged.size(); ++i) merged[i] += b.sums[i];
    CHECK(merged == one.sums);
    return one;
}

}  // namespace sweeptrace::testing

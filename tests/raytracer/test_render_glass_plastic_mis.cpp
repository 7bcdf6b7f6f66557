// The integrator with the rough dielectric and the coated diffuse: next event estimation + MIS
// and BSDF-only sampling converge to the same image, also where the coated diffuse's mirror
// lobe (delta, never evaluated) meets a light. Its power is that of a whole-image comparison at
// these sample counts (a 10% error is rejected, below); a wrong density shows far more sharply
// in the BSDF-level chi-square and sample/eval checks (test_render_bsdf_chi_square.cpp): eval's
// pdf tripled for the rough glass, or the plastic's lobe probability dropped, pass here (the
// glass's transmitted NEE is mostly shadowed by the sphere itself, the plastic's mirror lobe is
// ~5% of its samples) and fail there.
#include <catch2/catch.hpp>

#include "convergence_harness.hpp"
#include "render_test_scenes.hpp"

using namespace sweeptrace;

TEST_CASE("render: NEE+MIS and BSDF-only sampling agree with rough glass and plastic", "[render][mis]") {
    Scene s = test::two_light_scene(24, 18);
    // The red diffuse sphere becomes rough glass, the rough gold one red plastic, the floor and
    // back wall grey plastic (materials 1, 2, 0 of two_light_scene).
    s.materials[1].type = Material::Type::RoughDielectric;
    s.materials[1].roughness = 0.4f;
    s.materials[1].ior = 1.5f;
    s.materials[1].albedo = glm::vec3(1.0f);
    s.materials[2].type = Material::Type::CoatedDiffuse;
    s.materials[2].albedo = {0.7f, 0.1f, 0.05f};
    s.materials[0].type = Material::Type::CoatedDiffuse;
    const RenderResult nee = testing::render_with(s, AccelKind::Bvh, 128, 8, 11);
    const RenderResult bsdf = testing::render_with(s, AccelKind::Bvh, 1024, 8, 12, Sampling::BsdfOnly);
    CHECK(nee.stats.nonfinite_samples == 0);
    CHECK(bsdf.stats.nonfinite_samples == 0);
    // Two independent estimates: the difference of block means has the sum of their variances.
    Image both = nee.variance;
    for (std::size_t i = 0; i < both.pixels.size(); ++i) both.pixels[i] += bsdf.variance.pixels[i];
    BlockTestOptions o;
    o.block = 6;
    o.golden_is_8bit = false;
    const BlockTestResult t = block_test(bsdf.image, nee.image, both, o);
    INFO(t.summary());
    CHECK(t.pass());
    // The comparison has power: one estimator 10% too bright is rejected.
    Image brighter = nee.image;
    for (auto& p : brighter.pixels) p *= 1.1f;
    Image brighter_var = both;
    for (std::size_t i = 0; i < both.pixels.size(); ++i) brighter_var.pixels[i] = nee.variance.pixels[i] * 1.21f + bsdf.variance.pixels[i];
    CHECK_FALSE(block_test(bsdf.image, brighter, brighter_var, o).pass());
}

// The thin dielectric sheet (render/materials/bsdf.hpp): its reflectance is the sum of the bounces between
// its two interfaces, it conserves energy exactly at every angle (weights and probabilities),
// and a sheet in a white furnace is invisible.
#include <catch2/catch.hpp>

#include <cmath>

#include "convergence_harness.hpp"
#include "raytracer/render/materials/bsdf.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// Fresnel reflectance of one interface in long double, for the reference series.
long double fresnel_ld(long double cos_i, long double eta) {
    const long double sin2_t = (1 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1) return 1;
    const long double cos_t = std::sqrt(1 - sin2_t);
    const long double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const long double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return (rs * rs + rp * rp) / 2;
}

SurfaceHit hit_with_normal(const glm::vec3& n) {
    SurfaceHit h;
    h.normal = n;
    h.shading_normal = n;
    return h;
}

}  // namespace

TEST_CASE("thin dielectric: reflectance is R + T^2 R (1 + R^2 + ...), summed bounce by bounce", "[render][bsdf]") {
    for (float ior : {1.1f, 1.33f, 1.5f, 2.4f})
        for (int k = 0; k <= 20; ++k) {
            const float cos_i = std::max(1e-3f, k / 20.0f);
            const long double r = fresnel_ld(cos_i, ior), t = 1 - r;
            long double series = r, bounce = t * t * r;  // light leaving the front after 2k + 1 reflections
            for (int b = 0; b < 200000 && bounce > 1e-30L; ++b, bounce *= r * r) series += bounce;  // R ~ 0.994 at grazing: many terms
            INFO("ior " << ior << ", cos " << cos_i);
            CHECK(thin_dielectric_reflectance(cos_i, ior) == Approx(static_cast<double>(series)).epsilon(1e-5));
            CHECK(thin_dielectric_reflectance(cos_i, ior) >= static_cast<float>(r) * (1 - 1e-5f));
            CHECK(thin_dielectric_reflectance(cos_i, ior) <= 1.0f);
        }
    CHECK(thin_dielectric_reflectance(1.0f, 1.5f) == Approx(0.08f / 1.04f).epsilon(1e-4));  // R = 0.04 at normal incidence
}

TEST_CASE("thin dielectric: the lobes' probabilities are R' and 1 - R', weights 1 and the tint, from both sides",
          "[render][bsdf][furnace]") {
    Material sheet;
    sheet.type = Material::Type::ThinDielectric;
    sheet.ior = 1.5f;
    sheet.albedo = glm::vec3(1.0f);
    REQUIRE(is_delta(sheet));
    for (float side : {1.0f, -1.0f})
        for (float theta : {0.0f, 0.5f, 1.0f, 1.4f, 1.55f}) {
            const glm::vec3 wo = side * glm::vec3(std::sin(theta) * 0.6f, std::sin(theta) * 0.8f, std::cos(theta));
            const ShadingContext ctx = make_shading_context(hit_with_normal({0, 0, 1}), wo);
            const float r = thin_dielectric_reflectance(std::cos(theta), 1.5f);
            // Energy: over u0 uniform, E[weight] = R' 1 + (1 - R') 1 = 1 exactly; the lobes'
            // pdfs are the probabilities sample() uses.
            BsdfSample refl, trans;
            REQUIRE(sample_bsdf(sheet, ctx, 0.999f * r, 0.0f, 0.0f, refl));
            REQUIRE(sample_bsdf(sheet, ctx, r + 0.5f * (1.0f - r), 0.0f, 0.0f, trans));
            INFO("side " << side << ", theta " << theta);
            CHECK(refl.pdf == Approx(r));
            CHECK(trans.pdf == Approx(1.0f - r));
            CHECK(refl.pdf + trans.pdf == Approx(1.0f).epsilon(1e-6));
            CHECK(refl.weight == glm::vec3(1.0f));
            CHECK(trans.weight == glm::vec3(1.0f));
            CHECK(refl.wi.x == Approx(-wo.x).margin(1e-6));  // mirror
            CHECK(refl.wi.z == Approx(wo.z).margin(1e-6));
            CHECK(glm::length(trans.wi + wo) < 1e-5f);        // straight through
            CHECK(eval_bsdf(sheet, ctx, refl.wi).pdf == 0.0f);  // delta: nothing to evaluate
        }
    sheet.albedo = glm::vec3(0.5f, 0.7f, 0.9f);
    const ShadingContext ctx = make_shading_context(hit_with_normal({0, 0, 1}), glm::vec3(0, 0, 1));
    BsdfSample t;
    REQUIRE(sample_bsdf(sheet, ctx, 0.99f, 0.0f, 0.0f, t));
    CHECK(t.weight == sheet.albedo);  // the tint acts on transmission only
}

TEST_CASE("thin dielectric: a clear sheet in a white furnace is invisible at every angle", "[render][furnace]") {
    constexpr int size = 24;
    Scene scene = empty_scene(size, size);
    scene.background.color = glm::vec3(0.7f, 0.8f, 0.9f);
    scene.camera.position = {0.0f, 0.4f, 2.0f};
    scene.camera.look_at = {0.0f, 0.0f, 0.0f};
    scene.camera.vfov_degrees = 90.0f;  // angles from normal to grazing on the sheet
    Material sheet;
    sheet.type = Material::Type::ThinDielectric;
    sheet.ior = 1.5f;
    sheet.albedo = glm::vec3(1.0f);
    add_object(scene, collision::Quad{{-3.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 6.0f}, {6.0f, 0.0f, 0.0f}},
               add_material(scene, sheet), glm::mat4(1.0f), "sheet");
    Image truth(size, size);
    for (auto& p : truth.pixels) p = scene.background.color;
    for (AccelKind accel : {AccelKind::Bvh, AccelKind::Embree}) {
        const RenderResult r = render_with(scene, accel, 8, 4, 2);
        // Every path reflects or passes once and escapes: each sample reads the background times
        // a weight of exactly 1.
        const BlockTestResult t = test_against_truth(truth, r, 4, 1e-6, nullptr);
        INFO((accel == AccelKind::Bvh ? "bvh: " : "embree: ") << t.summary());
        CHECK(t.pass());
        for (const glm::vec3& p : r.image.pixels) REQUIRE(p.g == Approx(0.8f).epsilon(1e-6));
    }
}

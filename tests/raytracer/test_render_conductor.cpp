// The conductor: its complex-IOR Fresnel term against closed forms and a long-double evaluation of
// the textbook complex formula, its limits (k = 0 is the dielectric, eta = k, huge k a perfect
// mirror), the named metals' table against its stated normal-incidence reflectance, and energy: a
// mirror reflects exactly albedo F, a rough conductor in a white furnace never brightens and reads
// what its Fresnel term allows (sample/eval consistency is in test_render_bsdf.cpp, the chi-square
// test in test_render_bsdf_chi_square.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

#include "furnace_sphere.hpp"
#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/named_metals.hpp"
#include "render_test_stats.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;
using sweeptrace::test::Estimate;
using sweeptrace::test::z_bound;

namespace {

// r_s and r_p with complex cos theta_t = sqrt(1 - sin^2 / n^2), the textbook form (not the real
// closed form the renderer evaluates).
long double reference_fresnel(long double c, long double eta, long double k) {
    using C = std::complex<long double>;
    const C n(eta, k);
    const long double s2 = 1.0L - c * c;
    const C ct = std::sqrt(C(1.0L) - s2 / (n * n));
    const C rs = (c - n * ct) / (c + n * ct);
    const C rp = (n * c - ct) / (n * c + ct);
    return 0.5L * (std::norm(rs) + std::norm(rp));
}

long double normal_incidence(long double eta, long double k) {
    return ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
}

Material gold(float roughness) {
    Material m;
    m.type = Material::Type::Conductor;
    m.albedo = glm::vec3(1.0f);
    const NamedMetal au = *find_named_metal("Au");
    m.eta = au.eta;
    m.k = au.k;
    m.roughness = roughness;
    return m;
}

constexpr float kEtas[] = {0.05f, 0.13f, 0.4f, 1.0f, 1.5f, 3.0f, 20.0f};
constexpr float kKs[] = {0.0f, 0.01f, 0.5f, 2.4f, 4.0f, 8.0f, 20.0f};

}  // namespace

TEST_CASE("conductor Fresnel: normal incidence is ((eta-1)^2+k^2)/((eta+1)^2+k^2), grazing is 1", "[render][bsdf][conductor]") {
    for (float eta : kEtas)
        for (float k : kKs) {
            INFO("eta " << eta << " k " << k);
            const double ref = static_cast<double>(normal_incidence(eta, k));
            CHECK(std::abs(fresnel_conductor(1.0f, eta, k) - ref) <= 2e-6 * ref + 1e-7);
            CHECK(fresnel_conductor(0.0f, eta, k) == 1.0f);
            CHECK(fresnel_conductor(-0.5f, eta, k) == 1.0f);  // clamped to grazing
        }
    // Known values: silver-like (eta 0.13, k 3.9) reflects ~97%, aluminium-like (1.4, 7.6) ~91%.
    CHECK(fresnel_conductor(1.0f, 0.13f, 3.9f) == Approx(0.9676).epsilon(1e-3));
    CHECK(fresnel_conductor(1.0f, 1.38f, 7.64f) == Approx(0.9138).epsilon(1e-3));
}

TEST_CASE("conductor Fresnel: every angle agrees with a long-double evaluation of the complex formula", "[render][bsdf][conductor]") {
    // The real closed form (bsdf_conductor.cpp) keeps float's relative precision: no difference
    // of nearly equal terms. Bound: 2e-6 relative, 1e-7 absolute (near R = 0: eta ~ 1, k ~ 0).
    double worst = 0.0;
    for (float eta : kEtas)
        for (float k : kKs)
            for (int i = 0; i <= 200; ++i) {
                const float c = static_cast<float>(i) / 200.0f;
                // At grazing the textbook form is 0/0 when n = 1; its limit is 1.
                const long double ref = c == 0.0f ? 1.0L : reference_fresnel(c, eta, k);
                const float f = fresnel_conductor(c, eta, k);
                const double err = std::abs(static_cast<double>(f - ref));
                if (ref > 1e-3L) worst = std::max(worst, err / static_cast<double>(ref));
                INFO("eta " << eta << " k " << k << " cos " << c << ": " << f << " vs " << static_cast<double>(ref));
                REQUIRE(err <= 2e-6 * static_cast<double>(ref) + 1e-7);
            }
    WARN("conductor Fresnel: worst relative error where R > 1e-3: " << worst);
}

TEST_CASE("conductor Fresnel: k = 0 is the dielectric, eta = k and huge k behave as the formula says", "[render][bsdf][conductor]") {
    for (float eta : {1.33f, 1.5f, 2.4f, 0.75f, 1.0f / 1.5f})
        for (int i = 0; i <= 50; ++i) {
            const float c = static_cast<float>(i) / 50.0f;
            float cos_t = 0.0f;
            const float d = fresnel_dielectric(c, eta, cos_t);
            INFO("eta " << eta << " cos " << c);
            CHECK(std::abs(fresnel_conductor(c, eta, 0.0f) - d) <= 1e-5 + 1e-5 * d);  // incl. total internal reflection
        }
    // Index-matched (eta 1, k 0): nothing reflects at any angle but grazing.
    for (float c : {0.01f, 0.3f, 1.0f}) CHECK(fresnel_conductor(c, 1.0f, 0.0f) <= 1e-7f);
    // eta = k: Re(n^2) = 0, w = -sin^2 + 2 i eta^2; normal incidence (2 eta^2 - 2 eta + 1) / (2 eta^2 + 2 eta + 1).
    for (float e : {0.1f, 1.0f, 3.0f}) {
        CHECK(fresnel_conductor(1.0f, e, e) == Approx((2 * e * e - 2 * e + 1) / (2 * e * e + 2 * e + 1)).epsilon(2e-6));
        for (float c : {0.2f, 0.7f})
            CHECK(std::abs(fresnel_conductor(c, e, e) - reference_fresnel(c, e, e)) <= 2e-6L * reference_fresnel(c, e, e));
    }
    // k -> infinity: a perfect mirror at every angle; and the metals' dip toward grazing (R_p's
    // minimum, the "principal angle") stays below R at normal incidence.
    for (float c : {0.05f, 0.5f, 1.0f}) CHECK(fresnel_conductor(c, 1.0f, 1e4f) > 0.9999f);
    CHECK(fresnel_conductor(0.15f, 1.38f, 7.64f) < fresnel_conductor(1.0f, 1.38f, 7.64f));
}

TEST_CASE("named metals: every table entry is physical and reflects what the reduction printed", "[render][bsdf][conductor]") {
    // The normal-incidence reflectances tools/conductor_rgb.py printed next to the table
    // (scene/named_metals.cpp), to the 4 digits it printed: a typo in the table fails here.
    struct Expected {
        const char* name;
        float r0[3];
    };
    const Expected expected[] = {{"Ag", {0.9701f, 0.9605f, 0.9132f}}, {"Al", {0.9138f, 0.9214f, 0.9245f}},
                                 {"Au", {0.9936f, 0.7888f, 0.3372f}}, {"Cu", {0.9331f, 0.6398f, 0.5336f}},
                                 {"CuZn", {0.8952f, 0.7822f, 0.4136f}}, {"MgO", {0.0721f, 0.0731f, 0.0750f}},
                                 {"TiO2", {0.2334f, 0.2443f, 0.2738f}}};
    CHECK(named_metals().size() == std::size(expected));
    for (const Expected& e : expected) {
        const auto m = find_named_metal(e.name);
        REQUIRE(m);
        for (int c = 0; c < 3; ++c) {
            INFO(e.name << " channel " << c);
            CHECK(m->eta[c] > 0.0f);
            CHECK(m->k[c] >= 0.0f);
            CHECK(std::abs(fresnel_conductor(1.0f, m->eta[c], m->k[c]) - e.r0[c]) < 1.5e-4f);
        }
    }
    CHECK_FALSE(find_named_metal("au"));  // pbrt's spelling only
    CHECK_FALSE(find_named_metal("Gold"));
}

TEST_CASE("named metals: brass (CuZn) loads from a scene and reflects its closed form at normal incidence", "[render][bsdf][conductor]") {
    // pbrt-v4's metal-CuZn reduced by tools/conductor_rgb.py: R0 0.8952 0.7822 0.4136 (docs/conductors.md).
    const test::TempDir dir;
    const Scene scene = load_scene(dir.write("brass.json", R"({
  "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "film": { "width": 4, "height": 4 },
  "materials": { "brass": { "type": "conductor", "metal": "CuZn" } },
  "objects": [{ "type": "sphere", "radius": 1, "material": "brass" }] })"));
    REQUIRE(scene.materials.size() == 1);
    const Material& m = scene.materials[0];
    const NamedMetal brass = *find_named_metal("CuZn");
    CHECK(m.type == Material::Type::Conductor);
    CHECK(m.eta == brass.eta);
    CHECK(m.k == brass.k);
    const float printed[3] = {0.8952f, 0.7822f, 0.4136f};
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c);
        const long double closed = normal_incidence(m.eta[c], m.k[c]);
        CHECK(std::abs(fresnel_conductor(1.0f, m.eta[c], m.k[c]) - closed) <= 2e-6L * closed);
        CHECK(std::abs(closed - printed[c]) < 1.5e-4L);  // the table's 4 digits
    }
    // Brass is yellow: red over green over blue, less red than copper, more green.
    const NamedMetal cu = *find_named_metal("Cu");
    CHECK(normal_incidence(brass.eta[0], brass.k[0]) < normal_incidence(cu.eta[0], cu.k[0]));
    CHECK(normal_incidence(brass.eta[1], brass.k[1]) > normal_incidence(cu.eta[1], cu.k[1]));
}

TEST_CASE("conductor: roughness 0 is a mirror of weight albedo F(cos theta), a delta lobe", "[render][bsdf][conductor]") {
    Material m = gold(0.0f);
    m.albedo = {1.0f, 0.5f, 0.25f};
    REQUIRE(is_delta(m));
    for (float theta : {0.0f, 0.6f, 1.3f}) {
        const glm::vec3 wo{std::sin(theta), 0.0f, std::cos(theta)};
        const ShadingContext ctx = make_shading_context(flat_z_hit(), wo);
        BsdfSample s;
        REQUIRE(sample_bsdf(m, ctx, 0.5f, 0.5f, 0.5f, s));
        CHECK(s.delta);
        CHECK(glm::length(s.wi - glm::vec3(-wo.x, -wo.y, wo.z)) < 1e-6f);
        const glm::vec3 f = fresnel_conductor(ctx.wo_local.z, m.eta, m.k);
        for (int c = 0; c < 3; ++c) CHECK(s.weight[c] == m.albedo[c] * f[c]);
        CHECK(eval_bsdf(m, ctx, s.wi).pdf == 0.0f);
    }
}

TEST_CASE("conductor: a rough gold sphere in a white furnace reads its Fresnel term times the metal's albedo", "[render][furnace][conductor]") {
    // One reflection then the environment (L = 1): a pixel's expectation is the directional
    // albedo E[F(wo.h) G2/G1]. Gold's blue F rises monotonically from F(1) = 0.337 at normal
    // incidence to 1 at grazing (checked below on a 0.1-degree grid), so per sample
    // F(1) w <= w_gold <= w, w the untinted white metal's weight G2/G1 for the same microfacet:
    // the gold sphere's blue lies between F(1) and 1 times the white metal sphere's (the same
    // seed draws the same microfacets), and never above the environment.
    const Material au = gold(0.0f);
    for (int i = 1; i <= 900; ++i) {
        const float a = static_cast<float>(i) * 0.1f * kPi / 180.0f, b = static_cast<float>(i - 1) * 0.1f * kPi / 180.0f;
        // Up to the function's stated float error (it is flat near normal incidence).
        REQUIRE(fresnel_conductor(std::cos(a), au.eta.z, au.k.z) >= fresnel_conductor(std::cos(b), au.eta.z, au.k.z) * (1.0f - 4e-6f));
    }
    for (float roughness : {0.3f, 1.0f}) {
        const RenderResult g = render_with(sphere_furnace(gold(roughness), glm::vec3(1.0f)), AccelKind::Bvh, 16, 8, 5);
        Material white = gold(roughness);
        white.type = Material::Type::Metal;  // Schlick with F0 = 1: F = 1 at every angle
        const RenderResult w = render_with(sphere_furnace(white, glm::vec3(1.0f)), AccelKind::Bvh, 16, 8, 5);
        for (const BlockMean& b : sphere_blocks(g)) {
            INFO("roughness " << roughness << ": green block mean " << b.mean << " +- " << b.standard_error);
            CHECK(b.mean <= 1.0 + z_bound(1000) * b.standard_error + 1e-6);
        }
        const double f1 = fresnel_conductor(1.0f, gold(roughness).eta.z, gold(roughness).k.z);
        const std::vector<BlockMean> gold_blue = sphere_blocks(g, 2), white_blue = sphere_blocks(w, 2);
        for (std::size_t i = 0; i < gold_blue.size(); ++i) {
            const double gb = gold_blue[i].mean, wb = white_blue[i].mean;
            INFO("roughness " << roughness << " block " << i << ": gold blue " << gb << ", white " << wb << ", F(1) " << f1);
            // Same samples, so the bounds hold sample by sample, up to float rounding.
            CHECK(gb >= f1 * wb * (1.0 - 1e-5));
            CHECK(gb <= wb * (1.0 + 1e-5));
            if (roughness == 0.3f) CHECK(gb <= 0.5 * wb);  // microfacets tilted past 60 degrees are rare
        }
    }
}

TEST_CASE("conductor: directional albedo at low roughness approaches F at the mirror angle", "[render][bsdf][conductor]") {
    // Roughness 0.1 (alpha 0.01): microfacet normals within ~1 degree, masking loss < 0.2% up to
    // 78 degrees (test_render_metal_energy.cpp); the tilt changes wo.h to first order
    // symmetrically (+-), so F's slope cancels and E[weight] = F(cos theta) within the 0.2% loss
    // plus second-order terms (alpha^2 = 1e-4 times F''): 0.3% is the bound.
    const Material m = gold(0.1f);
    for (float theta : {0.2f, 0.6f, 1.0f}) {
        const ShadingContext ctx = make_shading_context(flat_z_hit(), {std::sin(theta), 0.0f, std::cos(theta)});
        Rng rng(77, 0, 0);
        Estimate e;
        for (int i = 0; i < 20000; ++i) {
            BsdfSample s;
            e.add(sample_bsdf(m, ctx, rng.uniform(), rng.uniform(), rng.uniform(), s) ? s.weight.b : 0.0);
        }
        const double f = fresnel_conductor(std::cos(theta), m.eta.z, m.k.z);
        INFO("theta " << theta << ": " << e.mean << " +- " << e.standard_error() << " vs F " << f);
        CHECK(std::abs(e.mean - f) <= 0.003 * f + z_bound(3) * e.standard_error());
    }
}

TEST_CASE("conductor Fresnel: stays in [0, 1] for extreme indices and angles", "[render][bsdf][conductor]") {
    Rng rng(123, 0, 0);
    for (int i = 0; i < 200000; ++i) {
        const float eta = std::pow(10.0f, -4.0f + 8.0f * rng.uniform());
        const float k = i % 5 == 0 ? 0.0f : std::pow(10.0f, -4.0f + 8.0f * rng.uniform());
        const float c = i % 7 == 0 ? 0.0f : i % 7 == 1 ? 1.0f : rng.uniform();
        const float f = fresnel_conductor(c, eta, k);
        INFO("eta " << eta << " k " << k << " cos " << c);
        REQUIRE(std::isfinite(f));
        REQUIRE(f >= 0.0f);
        REQUIRE(f <= 1.0f + 1e-6f);
    }
}

TEST_CASE("conductor: \"distribution\": \"beckmann\" loads, an unknown one is refused, and its tails are far narrower than GGX's", "[render][bsdf][conductor]") {
    const test::TempDir dir;
    const auto scene_with = [&](const std::string& name, const std::string& distribution) {
        return dir.write(name, R"({
  "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "film": { "width": 4, "height": 4 },
  "materials": { "lamp": { "type": "conductor", "metal": "Au", "roughness": 0.5, "distribution": ")" +
                                   distribution + R"(" } },
  "objects": [{ "type": "sphere", "radius": 1, "material": "lamp" }] })");
    };
    CHECK(load_scene(scene_with("b.json", "beckmann")).materials[0].microfacet == Material::Microfacet::Beckmann);
    CHECK(load_scene(scene_with("g.json", "ggx")).materials[0].microfacet == Material::Microfacet::Ggx);
    CHECK_THROWS_WITH(load_scene(scene_with("p.json", "phong")), Catch::Contains("unknown distribution \"phong\"") &&
                                                                     Catch::Contains("materials.lamp.distribution"));
    // At alpha 0.25 (veach-bidir's lamp), seen along the normal: the same peak (both D are
    // 1 / (pi alpha^2) there), and light 1.4 rad off the normal, whose half vector is 0.7 rad off:
    // GGX's D falls like tan^-4 there, Beckmann's like exp(-tan^2 / alpha^2), 1/600 of it.
    Material ggx = gold(0.5f), beck = gold(0.5f);
    beck.microfacet = Material::Microfacet::Beckmann;
    SurfaceHit hit;
    hit.normal = hit.shading_normal = glm::vec3(0.0f, 0.0f, 1.0f);
    const ShadingContext ctx = make_shading_context(hit, glm::vec3(0.0f, 0.0f, 1.0f));
    const glm::vec3 mirror(0.0f, 0.0f, 1.0f), wide(std::sin(1.4f), 0.0f, std::cos(1.4f));
    const float peak_g = eval_bsdf(ggx, ctx, mirror).f_cos.x, peak_b = eval_bsdf(beck, ctx, mirror).f_cos.x;
    const float wide_g = eval_bsdf(ggx, ctx, wide).f_cos.x, wide_b = eval_bsdf(beck, ctx, wide).f_cos.x;
    INFO("at the mirror direction " << peak_g << " / " << peak_b << ", 1.4 rad off " << wide_g << " / " << wide_b);
    CHECK(std::abs(peak_b - peak_g) < 0.02f * peak_g);
    CHECK(wide_b > 0.0f);
    CHECK(wide_b < 0.01f * wide_g);
}

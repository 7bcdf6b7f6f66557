// The rough dielectric (render/materials/bsdf_rough_dielectric.cpp): it never creates energy (per incident
// angle, and as a glass sphere in a white furnace, the losses stated), it obeys the generalised
// reciprocity of a refracting BSDF, and as roughness -> 0 it becomes the smooth dielectric.
// Its pdf consistency is in test_render_bsdf_chi_square.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "furnace_sphere.hpp"
#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "render_test_stats.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;
using sweeptrace::test::Estimate;
using sweeptrace::test::z_bound;

namespace {

glm::vec3 dir_at(float theta, float phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

Material rough_glass(float roughness, float ior = 1.5f) {
    Material m;
    m.type = Material::Type::RoughDielectric;
    m.roughness = roughness;
    m.ior = ior;
    m.albedo = glm::vec3(1.0f);
    return m;
}

// The share of energy leaving by reflection and by transmission for light arriving from wo:
// sampled weights, the transmitted ones times eta^2 to undo the radiance scaling (1/eta^2) and
// count flux. Their sum can never exceed 1; what is missing is the single-scattering loss.
struct Albedo {
    Estimate reflected, transmitted, total;
};

Albedo directional_albedo(const Material& m, float theta, float side, int count, std::uint64_t seed) {
    const ShadingContext ctx = make_shading_context(flat_z_hit(), side * dir_at(theta, 0.4f));
    const float eta = ctx.front ? m.ior : 1.0f / m.ior;
    Rng rng(seed, 0, 0);
    Albedo a;
    for (int i = 0; i < count; ++i) {
        BsdfSample s;
        const float u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        double r = 0.0, t = 0.0;
        if (sample_bsdf(m, ctx, u0, u1, u2, s)) {
            if (glm::dot(s.wi, ctx.ng) > 0.0f) r = s.weight.g;
            else t = s.weight.g * eta * eta;
        }
        a.reflected.add(r);
        a.transmitted.add(t);
        a.total.add(r + t);
    }
    return a;
}

}  // namespace

TEST_CASE("rough dielectric: no energy gain at any angle and roughness, from either side", "[render][bsdf][furnace]") {
    // 9 angles x 5 roughnesses x 2 sides = 90 one-sided tests. Measured losses (the next test
    // prints the table; 200k samples each): roughness <= 0.1 below 0.2% up to 78 degrees and up
    // to 8% at 89; roughness 0.3 0.1-4% from outside and 1-9% from inside; roughness 1 (alpha 1)
    // 11-30% from outside and 44-58% from inside, where total internal reflection on tilted
    // microfacets sends much of the light into masked bounces. That is the energy of multiple
    // scattering between microfacets, which a single-scattering model drops.
    std::uint64_t seed = 1;
    for (float side : {1.0f, -1.0f})
        for (float roughness : {0.05f, 0.1f, 0.3f, 0.6f, 1.0f})
            for (int k = 0; k < 9; ++k) {
                const float theta = 0.05f + 1.5f * k / 8.0f;
                const Albedo a = directional_albedo(rough_glass(roughness), theta, side, 20000, ++seed);
                INFO("side " << side << " roughness " << roughness << " theta " << theta << ": total "
                             << a.total.mean << " +- " << a.total.standard_error());
                CHECK(a.total.mean <= 1.0 + z_bound(100) * a.total.standard_error() + 1e-6);
                // The single-scattering loss grows with roughness; smooth-ish glass keeps 98%.
                if (roughness <= 0.1f && theta < 1.3f) CHECK(a.total.mean > 0.98);
            }
}

TEST_CASE("rough dielectric: the table of losses", "[.][report]") {
    // Run: build/tests/raytracer_tests "rough dielectric: the table of losses"
    for (float side : {1.0f, -1.0f}) {
        std::printf("%s: loss = 1 - (reflected + eta^2 transmitted), 200k samples\nroughness", side > 0 ? "from outside (eta 1.5)" : "from inside (eta 1/1.5)");
        for (int k = 0; k < 9; ++k) std::printf(" %7.1f", (0.05f + 1.5f * k / 8.0f) * 180.0 / M_PI);
        std::printf("  (theta, degrees)\n");
        for (float roughness : {0.05f, 0.1f, 0.3f, 0.6f, 1.0f}) {
            std::printf("%9.2f", roughness);
            for (int k = 0; k < 9; ++k)
                std::printf(" %7.4f", 1.0 - directional_albedo(rough_glass(roughness), 0.05f + 1.5f * k / 8.0f, side, 200000, 7).total.mean);
            std::printf("\n");
        }
    }
}

TEST_CASE("rough dielectric: generalised reciprocity f(wo, wi) / n_o^2 = f(wi, wo) / n_i^2", "[render][bsdf]") {
    // A refracting BSDF for radiance carries the 1/eta^2 of radiance compression (Veach 1997,
    // eq. 5.14): with n_o, n_i the indices on wo's and wi's sides, f(wo, wi) / n_o^2 is
    // symmetric. Reflection is plainly symmetric (n_o = n_i). f = f_cos / |cos theta_i|.
    // Tolerance: ~40 float operations (1e-4 relative), plus the two sides' half vectors, equal
    // up to ~1e-7 rad of rounding, moving D by up to 4 tan(theta_h) / alpha^2 per radian ...
    Rng rng(3, 0, 0);
    const float ior = 1.5f;
    int checked = 0;
    for (float roughness : {0.1f, 0.4f, 1.0f})
        for (int i = 0; i < 2000; ++i) {
            const glm::vec3 a = uniform_sphere(rng.uniform(), rng.uniform());
            const glm::vec3 b = uniform_sphere(rng.uniform(), rng.uniform());
            const Material m = rough_glass(roughness, ior);
            const BsdfEval ab = eval_bsdf(m, make_shading_context(flat_z_hit(), a), b);
            const BsdfEval ba = eval_bsdf(m, make_shading_context(flat_z_hit(), b), a);
            const float n_a = a.z > 0.0f ? 1.0f : ior, n_b = b.z > 0.0f ? 1.0f : ior;
            const double f_ab = ab.f_cos.g / std::abs(b.z) / (n_a * n_a);
            const double f_ba = ba.f_cos.g / std::abs(a.z) / (n_b * n_b);
            const glm::dvec3 hd = glm::normalize(glm::dvec3(a) * double(n_a) + glm::dvec3(b) * double(n_b));
            const double tan_h = std::sqrt(std::max(0.0, 1.0 - hd.z * hd.z)) / std::max(1e-9, std::abs(hd.z));
            const double alpha = std::max(roughness * roughness, kMinMetalAlpha);
            // ... and, for refraction seen from inside near the critical angle, the outside
            // cosine sqrt(1 - sin^2 / eta^2) that Fresnel computes loses digits: relative error
            // ~ 6e-8 / cos_out^2 (cos_out = |outside direction . h|). In GGX's far tails (f < 1e-6,
    // against peaks of 1 to 1e4) these compound: there the margin is 1e-6 absolute.
            const glm::vec3 outside = a.z > 0.0f ? a : b;
            const double cos_out = std::abs(glm::dot(glm::dvec3(outside), hd));
            const double tolerance = 1e-4 + 4e-7 * tan_h / (alpha * alpha) + (a.z * b.z < 0.0f ? 1e-7 / (cos_out * cos_out) : 0.0);
            if (tolerance > 0.2) continue;  // h at the horizon or the critical angle: nothing to compare
            INFO("f_ab " << f_ab << " f_ba " << f_ba << ", tolerance " << tolerance);
            INFO("roughness " << roughness << " a " << a.x << " " << a.y << " " << a.z << " b " << b.x << " " << b.y << " " << b.z);
            REQUIRE(f_ab == Approx(f_ba).epsilon(tolerance).margin(1e-6));
            checked += f_ab > 1e-6;
        }
    CHECK(checked > 1500);  // both lobes took part, not only the far tails
}

TEST_CASE("rough dielectric: as roughness -> 0 it becomes the smooth dielectric", "[render][bsdf]") {
    // At roughness 0.01 (alpha clamped to 1e-3) the microfacet normals lie within ~0.1 degree of
    // the macro normal: the reflected and transmitted shares are F and (1 - F) within 2e-3 (F's
    // slope times that angle) plus noise. GGX's tail is heavy, P(tan theta_h > t) =
    // alpha^2 / (alpha^2 + t^2): 1.3% of the normals tilt beyond 0.5 degree, so not every
    // direction but 95% of them lie within 1 degree of the smooth lobes' mirror and Snell
    // directions. Roughness exactly 0 is the smooth dielectric itself.
    REQUIRE(is_delta(rough_glass(0.0f)));
    REQUIRE_FALSE(is_delta(rough_glass(0.01f)));
    // ior 1, an index-matched interface, is the smooth dielectric's straight pass too (the
    // microfacet transmission's Jacobian would divide by zero there).
    REQUIRE(is_delta(rough_glass(0.5f, 1.0f)));
    {
        const ShadingContext ctx = make_shading_context(flat_z_hit(), dir_at(0.6f, 0.4f));
        BsdfSample s;
        REQUIRE(sample_bsdf(rough_glass(0.5f, 1.0f), ctx, 0.5f, 0.3f, 0.7f, s));
        CHECK(glm::length(s.wi + dir_at(0.6f, 0.4f)) < 1e-5f);
        CHECK(s.weight.g == Approx(1.0f));
    }
    Material smooth = rough_glass(0.0f);
    smooth.type = Material::Type::Dielectric;
    for (float side : {1.0f, -1.0f})
        for (float theta : {0.1f, 0.5f, 0.7f, 1.0f, 1.4f}) {
            const Albedo a = directional_albedo(rough_glass(0.01f), theta, side, 20000, 50);
            const float eta = side > 0 ? 1.5f : 1.0f / 1.5f;
            float cos_t = 0.0f;
            const double f = fresnel_dielectric(std::cos(theta), eta, cos_t);
            INFO("side " << side << " theta " << theta << ": reflected " << a.reflected.mean << " F " << f);
            CHECK(std::abs(a.reflected.mean - f) < 2e-3 + z_bound(20) * a.reflected.standard_error());
            CHECK(std::abs(a.transmitted.mean - (1.0 - f)) < 2e-3 + z_bound(20) * a.transmitted.standard_error());
            const ShadingContext ctx = make_shading_context(flat_z_hit(), side * dir_at(theta, 0.4f));
            BsdfSample ref_r, ref_t;
            const bool has_r = sample_bsdf(smooth, ctx, 0.0f, 0.0f, 0.0f, ref_r);
            const bool has_t = f < 1.0 && sample_bsdf(smooth, ctx, 0.99999f, 0.0f, 0.0f, ref_t);
            Rng rng(51, 0, 0);
            int near = 0, drawn = 0;
            for (int i = 0; i < 2000; ++i) {
                BsdfSample s;
                if (!sample_bsdf(rough_glass(0.01f), ctx, rng.uniform(), rng.uniform(), rng.uniform(), s)) continue;
                const bool reflected = glm::dot(s.wi, ctx.ng) > 0.0f;
                const BsdfSample& ref = reflected ? ref_r : ref_t;
                REQUIRE((reflected ? has_r : has_t));
                near += glm::dot(s.wi, ref.wi) > std::cos(1.0 * M_PI / 180.0);
                ++drawn;
            }
            CHECK(near >= 0.95 * drawn);
        }
}

TEST_CASE("rough dielectric: a glass sphere in a white furnace never brightens, losses stated", "[render][furnace]") {
    // A clear sphere under a uniform environment L: each path refracts and reflects until it
    // escapes, so a lossless interface would read exactly L everywhere (the smooth case does, to
    // float rounding). The rough one may only lose energy: every 4x4 block of pixels covering the
    // sphere reads <= L within noise (one-sided, 6.2 sigma over the blocks). Measured mean
    // losses over the central 12 x 12 pixels, 16 spp, max depth 64: roughness 0 1e-7, 0.3 1.3%,
    // 1.0 64% (the light bounces inside many times, each losing the share the table of the
    // previous test gives). Printed by: raytracer_tests "rough dielectric: a glass sphere*" -s
    // | grep "mean over".
    for (float roughness : {0.0f, 0.3f, 1.0f})
        for (AccelKind accel : {AccelKind::Bvh, AccelKind::Embree}) {
            const RenderResult r = render_with(sphere_furnace(rough_glass(roughness), glm::vec3(1.0f)), accel, 16, 64, 5);
            CHECK(r.stats.nonfinite_samples == 0);
            Estimate over_sphere;
            for (const BlockMean& b : sphere_blocks(r)) {
                INFO("roughness " << roughness << ": block mean " << b.mean << " +- " << b.standard_error);
                CHECK(b.mean <= 1.0 + z_bound(1000) * b.standard_error + 1e-6);
                over_sphere.add(b.mean);
            }
            INFO("roughness " << roughness << ": mean over the sphere " << over_sphere.mean << " (loss "
                              << 1.0 - over_sphere.mean << ")");
            CHECK(over_sphere.n == 9);
            if (roughness == 0.0f) CHECK(over_sphere.mean == Approx(1.0).epsilon(1e-4));
            if (roughness <= 0.3f) CHECK(over_sphere.mean > 0.97);
        }
}

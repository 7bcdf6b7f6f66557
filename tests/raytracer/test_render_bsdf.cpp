// Each material's sampling, density and evaluation agree with each other and with closed forms.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "render_test_stats.hpp"

using namespace sweeptrace;
using sweeptrace::test::Estimate;
using sweeptrace::test::z_bound;

namespace {

SurfaceHit flat_hit(const glm::vec3& n) {
    SurfaceHit h;
    h.normal = n;
    h.shading_normal = n;
    return h;
}

glm::vec3 dir_at(float theta, float phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

Material metal(float roughness) {
    Material m;
    m.type = Material::Type::Metal;
    m.albedo = {0.9f, 0.6f, 0.3f};
    m.roughness = roughness;
    return m;
}

// For a non-delta material seen from wo: (1) every sample's pdf and weight equal eval's density
// and f_cos / pdf in that direction; (2) the density integrates, over the sphere, to the share of
// samples that succeed; (3) E[weight] from sampling equals the integral of f_cos computed
// independently by uniform sphere sampling.
void check_consistency(const Material& m, const glm::vec3& n, const glm::vec3& wo, std::uint64_t seed) {
    const SurfaceHit hit = flat_hit(n);
    const ShadingContext ctx = make_shading_context(hit, wo);
    Rng rng(seed, 0, 0);
    const int count = 100000;
    Estimate success, weight_r;
    for (int i = 0; i < count; ++i) {
        BsdfSample s;
        const float u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        const bool ok = sample_bsdf(m, ctx, u0, u1, u2, s);
        success.add(ok ? 1.0 : 0.0);
        weight_r.add(ok ? s.weight.r : 0.0);
        if (!ok) continue;
        REQUIRE_FALSE(s.delta);
        const BsdfEval e = eval_bsdf(m, ctx, s.wi);
        // Sampling and evaluation compute the half vector by different float paths (sampled vs
        // normalize(wo + wi)); GGX's density changes by at most ~2 tan(theta)/alpha^2 per radian,
        // so a few 1e-7 rad of direction error moves it by < 1e-5 relative for alpha >= 0.09;
        // 1e-3 leaves a wide margin while still catching any formula slip (factors of 2, pi).
        // At grazing wi the round trip to world and back can turn cos = 1e-7 into 0 (masking
        // then 1 instead of 1 - 1e-6): weights are of order 1, so 1e-5 absolute covers that.
        if (e.pdf == 0.0f) {
            REQUIRE(s.weight.r < 1e-5f);
            continue;
        }
        REQUIRE(e.pdf == Approx(s.pdf).epsilon(1e-3));
        REQUIRE(e.f_cos.r / e.pdf == Approx(s.weight.r).epsilon(1e-3).margin(1e-5));
        REQUIRE(e.f_cos.b / e.pdf == Approx(s.weight.b).epsilon(1e-3).margin(1e-5));
    }
    Estimate pdf_integral, f_integral;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 wi = uniform_sphere(rng.uniform(), rng.uniform());
        const BsdfEval e = eval_bsdf(m, ctx, wi);
        pdf_integral.add(e.pdf * 4.0 * M_PI);
        f_integral.add(e.f_cos.r * 4.0 * M_PI);
    }
    const double z = z_bound(2);
    CHECK(std::abs(pdf_integral.mean - success.mean) <
          z * std::sqrt(pdf_integral.variance_of_mean() + success.variance_of_mean()));
    CHECK(std::abs(f_integral.mean - weight_r.mean) <
          z * std::sqrt(f_integral.variance_of_mean() + weight_r.variance_of_mean()));
    CHECK(success.mean > 0.3);  // sanity: the sampler mostly works (rough, grazing loses ~half)
}

}  // namespace

TEST_CASE("bsdf: diffuse reflects albedo, samples cos/pi, and stays on wo's side", "[render][bsdf]") {
    Material m;
    m.albedo = {0.5f, 0.25f, 1.0f};
    const glm::vec3 n(0, 0, 1);
    for (float theta : {0.0f, 0.7f, 1.4f}) {
        const glm::vec3 wo = dir_at(theta, 0.3f);
        check_consistency(m, n, wo, 11);
        // Seen from below, the frame turns to wo's side: same albedo.
        check_consistency(m, n, -wo, 12);
    }
    const ShadingContext ctx = make_shading_context(flat_hit(n), dir_at(0.5f, 0.0f));
    CHECK(eval_bsdf(m, ctx, dir_at(2.5f, 1.0f)).pdf == 0.0f);  // no transmission
    const BsdfEval e = eval_bsdf(m, ctx, dir_at(0.0f, 0.0f));
    CHECK(e.f_cos.r == Approx(0.5f / M_PI));
    BsdfSample s;
    REQUIRE(sample_bsdf(m, ctx, 0.2f, 0.3f, 0.4f, s));
    CHECK(s.weight == m.albedo);
}

TEST_CASE("bsdf: rough metal (GGX, VNDF sampling) is self-consistent at several roughnesses and angles", "[render][bsdf]") {
    const glm::vec3 n = glm::normalize(glm::vec3(0.2f, -0.3f, 1.0f));
    std::uint64_t seed = 20;
    for (float roughness : {0.3f, 0.6f, 1.0f})
        for (float theta : {0.1f, 0.8f, 1.3f}) {
            const Frame f(n);
            check_consistency(metal(roughness), n, f.to_world(dir_at(theta, 2.0f)), ++seed);
        }
}

TEST_CASE("bsdf: rough conductor (GGX, complex-IOR Fresnel) is self-consistent at several roughnesses and angles", "[render][bsdf][conductor]") {
    const glm::vec3 n = glm::normalize(glm::vec3(0.2f, -0.3f, 1.0f));
    Material m;
    m.type = Material::Type::Conductor;
    m.albedo = {1.0f, 0.8f, 0.6f};
    m.eta = {0.2152f, 0.9697f, 1.2222f};  // copper (scene/named_metals.cpp)
    m.k = {3.3762f, 2.6244f, 2.3544f};
    std::uint64_t seed = 40;
    for (float roughness : {0.3f, 0.6f, 1.0f})
        for (float theta : {0.1f, 0.8f, 1.3f}) {
            const Frame f(n);
            m.roughness = roughness;
            check_consistency(m, n, f.to_world(dir_at(theta, 2.0f)), ++seed);
        }
}

TEST_CASE("bsdf: rough metal's directional albedo is at most F and near it when smooth-ish", "[render][bsdf]") {
    // Single-scattering GGX loses energy only through masking: at normal incidence and low
    // roughness the reflected energy is close to F0 = albedo; it never exceeds it (Schlick's F
    // only grows from F0 toward 1 at grazing, where the masking then dominates).
    const ShadingContext ctx = make_shading_context(flat_hit({0, 0, 1}), {0, 0, 1});
    Rng rng(5, 0, 0);
    Estimate e;
    for (int i = 0; i < 50000; ++i) {
        BsdfSample s;
        e.add(sample_bsdf(metal(0.3f), ctx, rng.uniform(), rng.uniform(), rng.uniform(), s) ? s.weight.r : 0.0);
    }
    CHECK(e.mean < 0.9 + z_bound(1) * e.standard_error());
    CHECK(e.mean > 0.85);
}

TEST_CASE("bsdf: a metal of roughness 0 is a mirror with Schlick's F, a delta lobe", "[render][bsdf]") {
    const Material m = metal(0.0f);
    REQUIRE(is_delta(m));
    const glm::vec3 wo = dir_at(0.6f, 1.0f);
    const ShadingContext ctx = make_shading_context(flat_hit({0, 0, 1}), wo);
    BsdfSample s;
    REQUIRE(sample_bsdf(m, ctx, 0.5f, 0.5f, 0.5f, s));
    CHECK(s.delta);
    CHECK(glm::length(s.wi - glm::vec3(-wo.x, -wo.y, wo.z)) < 1e-6f);
    const float c = std::cos(0.6f);
    CHECK(s.weight.g == Approx(0.6f + 0.4f * std::pow(1.0f - c, 5.0f)).epsilon(1e-5));
    CHECK(eval_bsdf(m, ctx, s.wi).pdf == 0.0f);
}

TEST_CASE("bsdf: exact dielectric Fresnel matches a long double reference and the known values", "[render][bsdf]") {
    float cos_t = 0.0f;
    CHECK(fresnel_dielectric(1.0f, 1.5f, cos_t) == Approx(0.04f).epsilon(1e-5));
    CHECK(cos_t == 1.0f);
    for (float eta : {1.33f, 1.5f, 2.4f, 1.0f / 1.5f})
        for (int i = 0; i <= 50; ++i) {
            const float ci = static_cast<float>(i) / 50.0f;
            const long double sin2 = (1.0L - (long double)ci * ci) / ((long double)eta * eta);
            long double ref = 1.0L;
            if (sin2 < 1.0L) {
                const long double ct = std::sqrt(1.0L - sin2);
                const long double rp = (eta * ci - ct) / (eta * ci + ct), rs = (ci - eta * ct) / (ci + eta * ct);
                ref = 0.5L * (rp * rp + rs * rs);
            }
            const float f = fresnel_dielectric(ci, eta, cos_t);
            // ~20 float operations: a relative error of a few 1e-6, except where F -> 0 at
            // Brewster's angle and absolute error matters: bound |error| by 1e-5 + 1e-5 F.
            REQUIRE(std::abs(f - static_cast<double>(ref)) <= 1e-5 + 1e-5 * static_cast<double>(ref));
        }
}

TEST_CASE("bsdf: dielectric reflects with probability F, refracts by Snell's law, reflects totally inside", "[render][bsdf]") {
    Material glass;
    glass.type = Material::Type::Dielectric;
    glass.ior = 1.5f;
    glass.albedo = glm::vec3(1.0f);
    REQUIRE(is_delta(glass));
    const glm::vec3 n(0, 0, 1);
    const float theta = 0.9f;
    // From outside (front): eta = 1.5.
    {
        const glm::vec3 wo = dir_at(theta, 0.4f);
        const ShadingContext ctx = make_shading_context(flat_hit(n), wo);
        float ct = 0.0f;
        const float f = fresnel_dielectric(std::cos(theta), 1.5f, ct);
        BsdfSample r, t;
        REQUIRE(sample_bsdf(glass, ctx, 0.999f * f, 0.0f, 0.0f, r));
        REQUIRE(sample_bsdf(glass, ctx, f + 0.5f * (1.0f - f), 0.0f, 0.0f, t));
        CHECK(r.wi.z > 0.0f);
        CHECK(r.pdf == Approx(f));
        CHECK(t.wi.z < 0.0f);
        CHECK(t.pdf == Approx(1.0f - f));
        // Snell: sin(theta_i) = 1.5 sin(theta_t); radiance scaled by 1/eta^2 entering.
        const float sin_t = std::sqrt(t.wi.x * t.wi.x + t.wi.y * t.wi.y);
        CHECK(std::sin(theta) == Approx(1.5f * sin_t).epsilon(1e-5));
        CHECK(t.weight.r == Approx(1.0f / 2.25f));
    }
    // From inside (wo below the outward normal): past the critical angle asin(1/1.5) = 0.7297,
    // every sample reflects.
    {
        const glm::vec3 wo = -dir_at(0.8f, 0.4f);
        const ShadingContext ctx = make_shading_context(flat_hit(n), wo);
        CHECK_FALSE(ctx.front);
        for (float u : {0.0f, 0.5f, 0.999f}) {
            BsdfSample s;
            REQUIRE(sample_bsdf(glass, ctx, u, 0.0f, 0.0f, s));
            CHECK(s.wi.z < 0.0f);  // stays inside
            CHECK(s.weight == glm::vec3(1.0f));
        }
        const glm::vec3 wo2 = -dir_at(0.3f, 0.4f);  // below the critical angle: leaves, x 2.25
        const ShadingContext ctx2 = make_shading_context(flat_hit(n), wo2);
        BsdfSample s;
        REQUIRE(sample_bsdf(glass, ctx2, 0.99f, 0.0f, 0.0f, s));
        CHECK(s.wi.z > 0.0f);
        CHECK(s.weight.r == Approx(2.25f));
        CHECK(std::sin(0.3f) * 1.5f == Approx(std::sqrt(s.wi.x * s.wi.x + s.wi.y * s.wi.y)).epsilon(1e-5));
    }
}

TEST_CASE("bsdf: emission leaves the front side only unless two-sided, emissive material is black", "[render][bsdf]") {
    Material m;
    m.type = Material::Type::Emissive;
    m.emission = {1, 2, 3};
    const glm::vec3 n(0, 1, 0);
    CHECK(emitted_radiance(m, n, {0, 1, 0}) == m.emission);
    CHECK(emitted_radiance(m, n, {0, -1, 0}) == glm::vec3(0.0f));
    m.two_sided_emission = true;
    CHECK(emitted_radiance(m, n, {0, -1, 0}) == m.emission);
    CHECK_FALSE(scatters(m));
    BsdfSample s;
    CHECK_FALSE(sample_bsdf(m, make_shading_context(flat_hit(n), n), 0.5f, 0.5f, 0.5f, s));
}

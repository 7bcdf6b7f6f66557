// Sampled directions' densities match eval_bsdf's pdf, by the chi-square test of pbrt-v4 and
// Mitsuba (bsdf_chi_square.hpp), for every material with a non-delta lobe: diffuse, GGX metal,
// GGX and Beckmann conductor (gold's complex-IOR Fresnel),
// rough dielectric (from outside and from inside, where total internal reflection takes part),
// coated diffuse (a smooth coat's mirror lobe is the extra bin; a rough coat's is sampled). Roughness >= 0.3 (alpha >= 0.09): the
// bins are 5 degrees and the density integral per bin an 8 x 8 midpoint rule, fine enough for
// lobes a few degrees wide, not for near-mirrors (the roughness -> 0 limit has its own test in
// test_render_rough_dielectric.cpp). The thin dielectric and the smooth dielectric are delta
// only: their discrete probabilities are checked exactly in their own tests.
// Significance: 0.01 for the whole file, Sidak-split over its kTests tests; 200k samples each.
#include <catch2/catch.hpp>

#include <cmath>

#include "bsdf_chi_square.hpp"
#include "raytracer/render/materials/bsdf.hpp"

using namespace sweeptrace;
using sweeptrace::test::chi_square_alpha;
using sweeptrace::test::chi_square_bsdf;

namespace {

constexpr int kTests = 54, kSamples = 200000;

SurfaceHit tilted_hit() {
    SurfaceHit h;
    h.normal = glm::normalize(glm::vec3(0.2f, -0.3f, 1.0f));
    h.shading_normal = h.normal;
    return h;
}

void check_chi_square(const Material& m, float theta, float side, std::uint64_t seed) {
    const SurfaceHit hit = tilted_hit();
    const Frame f(hit.normal);
    const glm::vec3 wo = side * f.to_world({std::sin(theta) * std::cos(2.0f), std::sin(theta) * std::sin(2.0f), std::cos(theta)});
    const ShadingContext ctx = make_shading_context(hit, wo);
    const test::ChiSquareResult r = chi_square_bsdf(m, ctx, kSamples, seed);
    INFO("theta " << theta << " side " << side << " roughness " << m.roughness << ": " << r.summary());
    CHECK(r.p_value > chi_square_alpha(kTests));
    CHECK(test::sample_eval_mismatches(m, ctx, 20000, seed) == 0);
}

Material make(Material::Type type, float roughness) {
    Material m;
    m.type = type;
    m.roughness = roughness;
    m.albedo = glm::vec3(1.0f);
    return m;
}

}  // namespace

TEST_CASE("chi-square: diffuse samples follow its density", "[render][bsdf][chi2]") {
    check_chi_square(make(Material::Type::Diffuse, 0.0f), 0.7f, 1.0f, 1);
}

TEST_CASE("chi-square: diffuse with transmittance (pbrt's diffusetransmission) samples both sides by its density", "[render][bsdf][chi2]") {
    Material m = make(Material::Type::Diffuse, 0.0f);
    m.albedo = glm::vec3(0.3f, 0.25f, 0.2f);
    m.transmittance = glm::vec3(0.6f, 0.5f, 0.4f);
    for (float side : {1.0f, -1.0f}) check_chi_square(m, 0.7f, side, 2);
}

TEST_CASE("chi-square: GGX metal samples follow its density", "[render][bsdf][chi2]") {
    std::uint64_t seed = 10;
    for (float roughness : {0.3f, 0.6f, 1.0f})
        for (float theta : {0.2f, 0.9f, 1.4f}) {
            Material m = make(Material::Type::Metal, roughness);
            m.albedo = {0.9f, 0.6f, 0.3f};
            check_chi_square(m, theta, 1.0f, ++seed);
        }
}

TEST_CASE("chi-square: GGX conductor samples follow its density", "[render][bsdf][chi2][conductor]") {
    std::uint64_t seed = 90;
    for (float roughness : {0.3f, 0.6f, 1.0f})
        for (float theta : {0.2f, 0.9f, 1.4f}) {
            Material m = make(Material::Type::Conductor, roughness);
            m.eta = {0.4769f, 0.3938f, 1.6048f};  // gold (scene/named_metals.cpp)
            m.k = {17.1602f, 2.3489f, 1.7027f};
            check_chi_square(m, theta, 1.0f, ++seed);
        }
}

TEST_CASE("chi-square: Beckmann conductor samples follow its density", "[render][bsdf][chi2][conductor]") {
    std::uint64_t seed = 120;
    for (float roughness : {0.5f, 1.0f})
        for (float theta : {0.2f, 0.9f, 1.4f}) {
            Material m = make(Material::Type::Conductor, roughness);
            m.microfacet = Material::Microfacet::Beckmann;
            m.eta = {0.4769f, 0.3938f, 1.6048f};  // gold (scene/named_metals.cpp)
            m.k = {17.1602f, 2.3489f, 1.7027f};
            check_chi_square(m, theta, 1.0f, ++seed);
        }
}

TEST_CASE("chi-square: rough dielectric samples follow its density, from both sides", "[render][bsdf][chi2]") {
    std::uint64_t seed = 30;
    for (float side : {1.0f, -1.0f})
        for (float roughness : {0.3f, 0.6f, 1.0f})
            for (float theta : {0.2f, 0.9f, 1.4f}) {
                Material m = make(Material::Type::RoughDielectric, roughness);
                m.ior = 1.5f;
                check_chi_square(m, theta, side, ++seed);
            }
}

TEST_CASE("chi-square: coated diffuse samples follow its density (smooth coat: the mirror lobe as the extra bin)", "[render][bsdf][chi2]") {
    std::uint64_t seed = 60;
    for (float roughness : {0.0f, 0.3f, 0.7f})
        for (float theta : {0.2f, 0.9f, 1.4f}) {
            Material m = make(Material::Type::CoatedDiffuse, roughness);
            m.albedo = {0.6f, 0.3f, 0.1f};
            m.ior = 1.5f;
            check_chi_square(m, theta, 1.0f, ++seed);
        }
}

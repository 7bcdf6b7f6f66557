// The microfacet materials never return a non-finite weight or density: random and edge inputs
// (normal incidence, grazing wo, shading normals tilted off the geometric one, roughness 0, tiny
// and 1, ior 1 and near 1) through sample_bsdf and eval_bsdf. (It found ior 1 rough glass, whose
// transmission Jacobian divided by zero: that is now the smooth dielectric's straight pass.)
// Run under ASan + UBSan by the CI's sanitizer pass.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/sampling/random.hpp"

using namespace sweeptrace;

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

TEST_CASE("bsdf: rough glass, coated diffuse and metal stay finite on random and edge inputs", "[render][bsdf]") {
    Rng rng(99, 0, 0);
    const Material::Type types[] = {Material::Type::RoughDielectric, Material::Type::CoatedDiffuse, Material::Type::Metal};
    const float iors[] = {1.0f, 1.0001f, 1.5f};  // few: the coat builds a table per ior (~0.2 s)
    for (int i = 0; i < 100000; ++i) {
        Material m;
        m.type = types[i % 3];
        const int k = i % 7;
        m.roughness = k == 0 ? 0.0f : k == 1 ? 1e-4f : k == 2 ? 1.0f : rng.uniform();
        m.ior = iors[(i / 3) % 3];  // every type meets every ior
        m.albedo = glm::vec3(rng.uniform(), rng.uniform(), i % 4 == 0 ? 1.0f : rng.uniform());
        SurfaceHit h;
        h.normal = uniform_sphere(rng.uniform(), rng.uniform());
        const glm::vec3 tilt = 0.3f * uniform_sphere(rng.uniform(), rng.uniform());
        h.shading_normal = i % 2 ? h.normal : glm::normalize(h.normal + tilt);
        glm::vec3 wo = uniform_sphere(rng.uniform(), rng.uniform());
        if (i % 11 == 0) wo = h.normal;
        if (i % 13 == 0) wo = glm::normalize(glm::cross(h.normal, wo) + 1e-7f * h.normal);
        const ShadingContext ctx = make_shading_context(h, wo);
        INFO("case " << i << ": type " << static_cast<int>(m.type) << ", roughness " << m.roughness << ", ior " << m.ior);
        BsdfSample s;
        if (sample_bsdf(m, ctx, rng.uniform(), rng.uniform(), rng.uniform(), s)) {
            REQUIRE(std::isfinite(s.pdf));
            REQUIRE(s.pdf > 0.0f);
            REQUIRE(finite(s.weight));
            if (!s.delta) REQUIRE(std::isfinite(eval_bsdf(m, ctx, s.wi).pdf));
        }
        const BsdfEval e = eval_bsdf(m, ctx, uniform_sphere(rng.uniform(), rng.uniform()));
        REQUIRE(std::isfinite(e.pdf));
        REQUIRE(finite(e.f_cos));
    }
}

#include "raytracer/render/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "raytracer/render/bsdf.hpp"
#include "raytracer/render/environment_light.hpp"
#include "raytracer/render/sampling.hpp"
#include "raytracer/render/texture.hpp"

namespace sweeptrace {

glm::vec3 background_radiance(const Background& bg, const glm::vec3& dir) {
    if (bg.kind == Background::Kind::Constant) return bg.color;
    if (bg.kind == Background::Kind::Environment) return environment_radiance(bg, dir);
    const float t = std::clamp(dir.y, 0.0f, 1.0f);
    return (1.0f - t) * bg.horizon + t * bg.zenith;
}

PathIntegrator::PathIntegrator(const Scene& scene, const Accel& accel, const LightSet& lights, int max_depth,
                               Sampling sampling, PlantedDefect defect)
    : scene_(scene), accel_(accel), lights_(lights), max_depth_(max_depth), sampling_(sampling), defect_(defect) {}

collision::Ray PathIntegrator::continue_ray(const SurfaceHit& hit, const glm::vec3& dir) const {
    if (defect_ == PlantedDefect::NoRayOffset) return collision::Ray{hit.point, dir};  // planted: acne
    return spawn_ray(hit, dir);
}

collision::Ray PathIntegrator::shadow_ray(const SurfaceHit& hit, const LightSample& ls) const {
    if (ls.at_infinity) return spawn_ray(hit, ls.wi);  // a directional light: no end to stop short of
    const glm::vec3& target = ls.point;
    collision::Ray r = spawn_ray_to(hit, target, ls.point_error, ls.normal);
    if (defect_ == PlantedDefect::NoRayOffset) {  // planted: the shadow ray starts on the surface
        r.origin = hit.point;
        r.dir = target - hit.point;
        r.tmin = 0.0f;
    }
    return r;
}

glm::vec3 PathIntegrator::radiance(collision::Ray ray, Rng& rng, std::uint64_t& rays) const {
    const bool nee = sampling_ == Sampling::NeeMis && !lights_.empty();
    glm::vec3 result(0.0f);
    glm::vec3 beta(1.0f);
    bool full_weight = true;    // the ray that found this vertex gets MIS weight 1
    float prev_pdf = 0.0f;      // BSDF density of that ray (non-delta only)
    glm::vec3 prev_point(0.0f); // where it left
    std::uint32_t prev_object = LightSet::kNoObject;  // and from which object's surface
    for (int depth = 1;; ++depth) {
        SurfaceHit hit;
        ++rays;
        if (!accel_.intersect(ray, hit)) {
            if (!lights_.background_is_light()) result += beta * background_radiance(scene_.background, ray.dir);
            if (lights_.has_distant()) result += beta * lights_.escaped_radiance(ray.dir, nee && !full_weight ? prev_pdf : 0.0f);
            break;
        }
        if (defect_ == PlantedDefect::FlippedNormals) {  // planted: inward normals
            hit.normal = -hit.normal;
            hit.shading_normal = -hit.shading_normal;
        }
        const Material& base = scene_.materials[scene_.objects[hit.object].material];
        std::optional<Material> textured;  // only for materials that read a texture (render/texture.hpp)
        const Material& mat = base.albedo_texture < 0 ? base : textured.emplace(textured_material(scene_, base, hit));
        const glm::vec3 wo = -ray.dir;

        const glm::vec3 le = emitted_radiance(mat, hit.normal, wo);
        if (le != glm::vec3(0.0f)) {
            float w = 1.0f;
            if (nee && !full_weight) w = power_heuristic(prev_pdf, lights_.pdf(prev_point, prev_object, hit));
            result += beta * le * w;
        }
        if (depth >= max_depth_ || !scatters(mat)) break;

        const ShadingContext ctx = make_shading_context(hit, wo);
        const bool delta = is_delta(mat);

        if (nee && !delta) {
            const float us = rng.uniform(), up = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
            LightSample ls;
            if (lights_.sample(hit.point, hit.object, us, up, u1, u2, ls)) {
                const BsdfEval e = eval_bsdf(mat, ctx, ls.wi);
                if (e.pdf > 0.0f) {
                    ++rays;
                    if (!accel_.occluded(shadow_ray(hit, ls))) {
                        const float w = ls.delta ? 1.0f : power_heuristic(ls.pdf, e.pdf);
                        result += beta * e.f_cos * ls.radiance * (w / ls.pdf);
                    }
                }
            }
        }

        BsdfSample bs;
        const float b0 = rng.uniform(), b1 = rng.uniform(), b2 = rng.uniform();
        if (!sample_bsdf(mat, ctx, b0, b1, b2, bs)) break;
        beta *= bs.weight;
        full_weight = bs.delta;
        prev_pdf = bs.pdf;
        prev_point = hit.point;
        prev_object = hit.object;

        if (depth >= 3) {
            const float q = std::min(1.0f, max_component(beta));
            if (!(rng.uniform() < q)) break;
            beta /= q;
        }
        ray = continue_ray(hit, bs.wi);
    }
    return result;
}

}  // namespace sweeptrace

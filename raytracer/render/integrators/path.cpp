#include "raytracer/render/integrators/path.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "raytracer/render/bsdf.hpp"
#include "raytracer/render/guiding_path_recorder.hpp"
#include "raytracer/render/guiding_sampler.hpp"
#include "raytracer/render/environment_light.hpp"
#include "raytracer/render/radiance_clamp.hpp"
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
                               Sampling sampling, PlantedDefect defect, RoulettePolicy roulette)
    : scene_(scene),
      accel_(accel),
      lights_(lights),
      max_depth_(max_depth),
      sampling_(sampling),
      defect_(defect),
      roulette_(roulette) {
    for (const Object& o : scene.objects) moving_ = moving_ || (scene.camera.shutter && o.motion.moving());
}

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

glm::vec3 PathIntegrator::radiance(collision::Ray ray, PixelSampler& sampler, std::uint64_t& rays,
                                   std::vector<GuideRecord>* records, float time, PathTally* tally,
                                   FeatureRecord* features) const {
    const bool nee = sampling_ == Sampling::NeeMis && !lights_.empty();
    GuidePathRecorder recorder(records);
    // Russian roulette judges a path by the throughput BSDF sampling would have given it: a
    // guided sample aimed at a bright light has a small weight (its density is high), and
    // roulette on that would end most of the very paths guiding found.
    float rr_scale = 1.0f;
    IndirectClamp limit(scene_.film.clamp_indirect);
    glm::vec3 result(0.0f);
    glm::vec3 beta(1.0f);
    float eta_scale = 1.0f;     // undoes the 1/eta^2 of refractions, for the roulette
    bool full_weight = true;    // the ray that found this vertex gets MIS weight 1
    const DirectionalQuadtree* prev_light_guide = nullptr;  // NEE's guide there (light_guide.hpp)
    float prev_pdf = 0.0f;      // BSDF density of that ray (non-delta only)
    glm::vec3 prev_point(0.0f); // where it left
    std::uint32_t prev_object = LightSet::kNoObject;  // and from which object's surface
    for (int depth = 1;; ++depth) {
        const int bounce = depth - 1;  // sampler dimensions: sample_dim::bounce(bounce, slot)
        SurfaceHit hit;
        ++rays;
        if (!(moving_ ? accel_.intersect(ray, time, hit) : accel_.intersect(ray, hit))) {
            if (!lights_.background_is_light())
                result += tally_found(tally, limit.found(beta * background_radiance(scene_.background, ray.dir), depth),
                                      PathKey::kBackground);
            if (lights_.has_distant())
                result += tally_found(tally, limit.found(beta * lights_.escaped_radiance(ray.dir, nee && !full_weight ? prev_pdf : 0.0f), depth),
                                      tally ? lights_.escaped_light(ray.dir) : -1);
            break;
        }
        if (defect_ == PlantedDefect::FlippedNormals) {  // planted: inward normals
            hit.normal = -hit.normal;
            hit.shading_normal = -hit.shading_normal;
        }
        const Material& base = scene_.materials[scene_.objects[hit.object].material];
        std::optional<Material> textured;  // only for materials that read a texture (render/texture.hpp)
        const Material& mat = !reads_texture(base) ? base : textured.emplace(textured_material(scene_, base, hit));
        const glm::vec3 wo = -ray.dir;
        if (features != nullptr) features->at_vertex(mat, hit, wo);

        const glm::vec3 le = emitted_radiance(mat, hit.normal, wo);
        if (le != glm::vec3(0.0f)) {
            float w = 1.0f;
            if (nee && !full_weight) w = power_heuristic(prev_pdf, lights_.pdf(prev_point, prev_object, hit, prev_light_guide));
            result += tally_found(tally, limit.found(beta * le * w, depth), tally ? lights_.light_of_object(hit.object) : -1);
        }
        if (depth >= max_depth_ || !scatters(mat)) break;

        const ShadingContext ctx = make_shading_context(hit, wo);
        const bool delta = is_delta(mat);
        limit.scatter_at(depth, delta);
        const bool learn = recorder.on() && is_guided(mat);
        const DirectionalQuadtree* guide = nullptr;
        const DirectionalQuadtree* light_guide = nullptr;
        if (guide_ != nullptr && guide_->active() && is_guided(mat)) {
            const std::uint32_t leaf = guide_->leaf_of(hit.point);
            guide = guide_->guide_at(leaf);
            if (nee) light_guide = guide_->light_guide_at(leaf);
            if (guide != nullptr) guide->prefetch();
            if (light_guide != nullptr) light_guide->prefetch();
            recorder.at_leaf(leaf);
        }

        if (nee && !delta) {
            const glm::vec2 uc = sampler.get2d(sample_dim::bounce(bounce, sample_dim::kLightChoice));  // and part
            const glm::vec2 u = sampler.get2d(sample_dim::bounce(bounce, sample_dim::kLightPoint));
            LightSample ls;
            if (lights_.sample(hit.point, hit.object, uc.x, uc.y, u.x, u.y, ls, light_guide)) {
                const BsdfEval e = eval_bsdf(mat, ctx, ls.wi);
                if (e.pdf > 0.0f) {
                    ++rays;
                    // The MIS weight only where the light is seen: at a guided vertex it costs a
                    // descent of the guide, and a blocked sample adds (and teaches) zero.
                    const collision::Ray shadow = shadow_ray(hit, ls);
                    if (!(moving_ ? accel_.occluded(shadow, time) : accel_.occluded(shadow))) {
                        const float w =
                            ls.delta ? 1.0f : power_heuristic(ls.pdf, guide ? guided_pdf(*guide, e.pdf, ls.wi) : e.pdf);
                        const glm::vec3 c = limit.light_sample(beta * e.f_cos * ls.radiance * (w / ls.pdf), depth);
                        result += c;
                        if (tally)
                            tally->add_light_sample(PathTally::kind_of(mat, false), scene_.objects[hit.object].material,
                                                    luminance(e.f_cos) * w / ls.pdf, c, ls.light);
                        if (learn) {
                            const glm::vec3 unweighted = ls.radiance / ls.pdf;
                            recorder.add_light_sample(hit.point, ctx.frame.n, ls.wi, unweighted * w, ls.square,
                                                      ls.on_square ? unweighted : glm::vec3(0.0f));
                        }
                    } else if (learn) {
                        recorder.add_light_sample(hit.point, ctx.frame.n, ls.wi, glm::vec3(0.0f), ls.square, glm::vec3(0.0f));
                    }
                }
            }
        }

        BsdfSample bs;
        const float b0 = sampler.get1d(sample_dim::bounce(bounce, sample_dim::kBsdfLobe));
        const glm::vec2 b = sampler.get2d(sample_dim::bounce(bounce, sample_dim::kBsdfDirection));
        float bsdf_pdf = 0.0f;
        if (guide ? !sample_guided(mat, ctx, *guide, sampler.get1d(sample_dim::bounce(bounce, sample_dim::kGuiding)),
                                   b0, b.x, b.y, bs, bsdf_pdf)
                  : !sample_bsdf(mat, ctx, b0, b.x, b.y, bs))
            break;
        beta *= bs.weight;
        if (tally) tally->scatter(PathTally::kind_of(mat, bs.delta), scene_.objects[hit.object].material, luminance(bs.weight));
        if (guide != nullptr && !bs.delta) rr_scale *= std::max(1.0f, bs.pdf / bsdf_pdf);
        if (learn && !bs.delta) recorder.add_vertex(hit.point, ctx.frame.n, bs.wi, bs.pdf, beta, result);
        full_weight = bs.delta;
        prev_light_guide = light_guide;
        prev_pdf = bs.pdf;
        prev_point = hit.point;
        prev_object = hit.object;

        const bool refracting = mat.type == Material::Type::Dielectric || mat.type == Material::Type::RoughDielectric;
        if (refracting && glm::dot(bs.wi, ctx.ng) < 0.0f) {
            const float eta = ctx.front ? mat.ior : 1.0f / mat.ior;  // refracted: weight had 1/eta^2
            eta_scale *= eta * eta;
        }
        // Drawn even when the survival probability is 1: classic() keeps the old random stream.
        if (depth >= roulette_.start_depth &&
            !survives_roulette(roulette_, depth, sampler.get1d(sample_dim::bounce(bounce, sample_dim::kRoulette)),
                               eta_scale, beta, rr_scale))
            break;
        ray = continue_ray(hit, bs.wi);
    }
    if (recorder.on()) recorder.finish(result);
    return result;
}

}  // namespace sweeptrace

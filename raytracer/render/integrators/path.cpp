#include "raytracer/render/integrators/path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/guiding/guiding_path_recorder.hpp"
#include "raytracer/render/guiding/guiding_sampler.hpp"
#include "raytracer/render/lights/background_light.hpp"
#include "raytracer/render/media/henyey_greenstein.hpp"
#include "raytracer/render/media/tracking.hpp"
#include "raytracer/render/film/radiance_clamp.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "raytracer/render/materials/texture.hpp"

namespace sweeptrace {

PathIntegrator::PathIntegrator(const Scene& scene, const Accel& accel, const LightSet& lights, int max_depth,
                               Sampling sampling, PlantedDefect defect, RoulettePolicy roulette)
    : scene_(scene),
      accel_(accel),
      lights_(lights),
      max_depth_(max_depth),
      sampling_(sampling),
      defect_(defect),
      roulette_(roulette),
      media_(scene) {
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

SurfaceHit PathIntegrator::point_hit(const glm::vec3& p, const glm::vec3& toward) {
    SurfaceHit h;
    h.point = p;
    h.normal = toward;  // point_error is 0: no offset along it
    h.object = LightSet::kNoObject;
    return h;
}

glm::vec3 PathIntegrator::medium_shadow(const SurfaceHit& from, const LightSample& ls, std::int32_t medium, float time,
                                        Rng& rng, std::uint64_t& rays) const {
    return media_.shadow_transmittance(accel_, shadow_ray(from, ls), medium, moving_, time, rng, rays,
                                       [&](const SurfaceHit& h) {
                                           return ls.at_infinity ? spawn_ray(h, ls.wi)
                                                                 : spawn_ray_to(h, ls.point, ls.point_error, ls.normal);
                                       });
}

glm::vec3 PathIntegrator::radiance(collision::Ray ray, PixelSampler& sampler, std::uint64_t& rays,
                                   std::vector<GuideRecord>* records, float time, PathTally* tally,
                                   FeatureRecord* features) const {
    // A sky without a portal is a light only where the guide learned it (sky_guide.hpp).
    const bool nee = sampling_ == Sampling::NeeMis && (!lights_.empty() || (guide_ != nullptr && lights_.sky_is_guidable()));
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
    SkyGuide prev_sky;                                      // and its sky guide (sky_guide.hpp)
    const SkyGuide* prev_sky_guide = nullptr;               // &prev_sky when it had one
    bool prev_recorded = false;  // that vertex's continuation went to the recorder (add_vertex)
    float prev_pdf = 0.0f;      // BSDF density of that ray (non-delta only)
    glm::vec3 prev_point(0.0f); // where it left
    std::uint32_t prev_object = LightSet::kNoObject;  // and from which object's surface
    // Media (render/media/): the medium the ray travels in (-1 vacuum), the path's own random
    // stream for delta and ratio tracking, and spectral MIS's hero channel and ratios
    // (tracking.hpp). In a scene without media none of them is used.
    std::int32_t medium = scene_.camera.medium;
    Rng medium_rng;
    int hero = 0;
    glm::vec3 r_u(1.0f);
    if (media_.active()) {
        medium_rng = sampler.stream(kMediumStream);
        hero = std::min(2, static_cast<int>(medium_rng.uniform() * 3.0f));
    }
    for (int depth = 1;; ++depth) {
        const int bounce = depth - 1;  // sampler dimensions: sample_dim::bounce(bounce, slot)
        SurfaceHit hit;
        ++rays;
        const bool found = moving_ ? accel_.intersect(ray, time, hit) : accel_.intersect(ray, hit);
        if (medium >= 0) {
            // Free flight to the surface (or without end): a medium vertex takes this depth's
            // place, with the same sampler slots a surface vertex would use.
            const FlightResult flight = delta_track(media_.model(medium), ray.origin, ray.dir, ray.tmin,
                                                    found ? hit.t : std::numeric_limits<float>::infinity(), hero,
                                                    medium_rng, beta, r_u, true);
            if (flight.emitted != glm::vec3(0.0f)) result += tally_found(tally, limit.found(flight.emitted, depth), PathKey::kMediumEmission);
            if (flight.event == Flight::Absorbed) break;
            if (flight.event == Flight::Scattered) {
                if (depth >= max_depth_) break;
                const glm::vec3 p = ray.at(flight.t);
                const float g = media_.model(medium).g();
                limit.scatter_at(depth, false);
                if (nee) {
                    const glm::vec2 uc = sampler.get2d(sample_dim::bounce(bounce, sample_dim::kLightChoice));
                    const glm::vec2 u = sampler.get2d(sample_dim::bounce(bounce, sample_dim::kLightPoint));
                    LightSample ls;
                    if (lights_.sample(p, LightSet::kNoObject, uc.x, uc.y, u.x, u.y, ls)) {
                        const float phase = hg_phase(glm::dot(ray.dir, ls.wi), g);
                        ++rays;
                        const glm::vec3 tr = medium_shadow(point_hit(p, ls.wi), ls, medium, time, medium_rng, rays);
                        if (tr != glm::vec3(0.0f)) {
                            const float w = ls.delta ? 1.0f : power_heuristic(ls.pdf, phase);
                            const glm::vec3 c = limit.light_sample(beta * tr * ls.radiance * (phase * w / ls.pdf), depth);
                            result += c;
                            if (tally) tally->add_light_sample(PathTally::Medium, PathTally::kNoMaterial, phase * w / ls.pdf, c, ls.light);
                        }
                    }
                }
                // The phase function's sample: its weight p / pdf is 1.
                const glm::vec2 b = sampler.get2d(sample_dim::bounce(bounce, sample_dim::kBsdfDirection));
                float pdf = 0.0f;
                const glm::vec3 wi = hg_sample(ray.dir, g, b.x, b.y, pdf);
                if (tally) tally->scatter(PathTally::Medium, PathTally::kNoMaterial, 1.0f);
                full_weight = false;
                prev_light_guide = nullptr;
                prev_sky_guide = nullptr;
                prev_recorded = false;
                prev_pdf = pdf;
                prev_point = p;
                prev_object = LightSet::kNoObject;
                if (depth >= roulette_.start_depth &&
                    !survives_roulette(roulette_, depth, sampler.get1d(sample_dim::bounce(bounce, sample_dim::kRoulette)),
                                       eta_scale, beta, rr_scale))
                    break;
                ray = collision::Ray{p, wi, 0.0f, std::numeric_limits<float>::infinity()};
                continue;
            }
        }
        if (!found) {
            const float mis_pdf = nee && !full_weight ? prev_pdf : 0.0f;
            if (!lights_.background_is_light()) {
                // MIS weighted only where the guided sky was a light at the previous vertex.
                const glm::vec3 le = background_radiance(scene_.background, ray.dir) *
                                     lights_.guided_sky_weight(prev_point, ray.dir, mis_pdf, prev_sky_guide);
                if (prev_recorded && lights_.sky_is_guidable()) recorder.add_sky_found(le);
                result += tally_found(tally, limit.found(beta * le, depth), PathKey::kBackground);
            }
            if (lights_.has_distant())
                result += tally_found(tally, limit.found(beta * lights_.escaped_radiance(prev_point, ray.dir, mis_pdf, prev_sky_guide), depth),
                                      tally ? lights_.escaped_light(ray.dir) : -1);
            break;
        }
        if (defect_ == PlantedDefect::FlippedNormals) {  // planted: inward normals
            hit.normal = -hit.normal;
            hit.shading_normal = -hit.shading_normal;
        }
        const MaterialParameters& base = scene_.materials[scene_.objects[hit.object].material];
        if (base.type == MaterialParameters::Type::Interface) {
            // Not a surface for light: the ray goes on into the medium on the far side, and the
            // crossing is no path vertex (pbrt-v4's SkipIntersection), so the depth stays.
            medium = media_.after_crossing(hit.object, hit.normal, ray.dir, medium);
            ray = spawn_ray(hit, ray.dir);
            --depth;
            continue;
        }
        std::optional<MaterialParameters> textured;  // only for materials that read a texture (render/materials/texture.hpp)
        const MaterialParameters& mat = !reads_texture(base) ? base : textured.emplace(textured_material(scene_, base, hit));
        const glm::vec3 wo = -ray.dir;
        if (features != nullptr) features->at_vertex(mat, hit, wo);

        const glm::vec3 le = emitted_radiance(mat, hit.normal, wo);
        if (le != glm::vec3(0.0f)) {
            float w = 1.0f;
            if (nee && !full_weight)
                w = power_heuristic(prev_pdf, lights_.pdf(prev_point, prev_object, hit, prev_light_guide, prev_sky_guide));
            result += tally_found(tally, limit.found(beta * le * w, depth), tally ? lights_.light_of_object(hit.object) : -1);
        }
        if (depth >= max_depth_ || !scatters(mat)) break;

        const ShadingContext ctx = make_shading_context(hit, wo);
        const bool delta = is_delta(mat);
        limit.scatter_at(depth, delta);
        const bool learn = recorder.on() && is_guided(mat);
        const DirectionalQuadtree* guide = nullptr;
        const DirectionalQuadtree* light_guide = nullptr;
        SkyGuide sky;
        const SkyGuide* sky_guide = nullptr;  // &sky where the leaf learned the sky
        if (guide_ != nullptr && guide_->active() && is_guided(mat)) {
            const std::uint32_t leaf = guide_->leaf_of(hit.point);
            guide = guide_->guide_at(leaf);
            if (nee) light_guide = guide_->light_guide_at(leaf);
            if (nee && lights_.sky_is_guidable()) sky.leaf = guide_->sky_guide_at(leaf);
            if (sky.leaf != nullptr) {
                // The sky's direct light is next event estimation's here, the path guide's main
                // catch: the continuation is the BSDF's own. Measured on the window room without
                // its portal (160 spp, seeds 7 and 8): the same RMSE in 0.7x the CPU time.
                sky.exit = guide_->sky_exit();
                sky_guide = &sky;
                guide = nullptr;
            }
            if (guide != nullptr) guide->prefetch();
            if (light_guide != nullptr) light_guide->prefetch();
            if (sky.leaf != nullptr) sky.leaf->prefetch();
            if (sky.exit != nullptr) sky.exit->prefetch();
            recorder.at_leaf(leaf);
        }

        if (nee && !delta) {
            const glm::vec2 uc = sampler.get2d(sample_dim::bounce(bounce, sample_dim::kLightChoice));  // and part
            const glm::vec2 u = sampler.get2d(sample_dim::bounce(bounce, sample_dim::kLightPoint));
            LightSample ls;
            if (lights_.sample(hit.point, hit.object, uc.x, uc.y, u.x, u.y, ls, light_guide, sky_guide)) {
                const BsdfEval e = eval_bsdf(mat, ctx, ls.wi);
                if (e.pdf > 0.0f) {
                    ++rays;
                    // The MIS weight only where the light is seen: at a guided vertex it costs a
                    // descent of the guide, and a blocked sample adds (and teaches) zero.
                    const collision::Ray shadow = shadow_ray(hit, ls);
                    // With media, a shadow ray passes interfaces and takes the transmittance of
                    // the media it crosses; in vacuum it is the plain visibility test.
                    glm::vec3 tr(1.0f);
                    if (media_.active())
                        tr = medium_shadow(hit, ls, media_.after_crossing(hit.object, hit.normal, ls.wi, medium), time,
                                           medium_rng, rays);
                    else if (moving_ ? accel_.occluded(shadow, time) : accel_.occluded(shadow))
                        tr = glm::vec3(0.0f);
                    if (tr != glm::vec3(0.0f)) {
                        const float w =
                            ls.delta ? 1.0f : power_heuristic(ls.pdf, guide ? guided_pdf(*guide, e.pdf, ls.wi) : e.pdf);
                        const glm::vec3 c = limit.light_sample(beta * e.f_cos * tr * ls.radiance * (w / ls.pdf), depth);
                        result += c;
                        if (tally)
                            tally->add_light_sample(PathTally::kind_of(mat, false), scene_.objects[hit.object].material,
                                                    luminance(e.f_cos) * w / ls.pdf, c, ls.light);
                        if (learn) {
                            const glm::vec3 unweighted = ls.radiance / ls.pdf;
                            recorder.add_light_sample(hit.point, ctx.frame.n, ls.wi, unweighted * w, ls.square,
                                                      ls.on_square ? unweighted : glm::vec3(0.0f), ls.guided_sky);
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
        prev_sky = sky;
        prev_sky_guide = sky_guide != nullptr ? &prev_sky : nullptr;
        prev_recorded = learn && !bs.delta;
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
        if (media_.active()) medium = media_.after_crossing(hit.object, hit.normal, bs.wi, medium);
        ray = continue_ray(hit, bs.wi);
    }
    if (recorder.on()) recorder.finish(result);
    return result;
}

}  // namespace sweeptrace

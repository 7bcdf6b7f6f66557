#include "raytracer/render/integrators/bdpt.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/integrators/bidir_mis.hpp"
#include "raytracer/render/integrators/mis_window.hpp"
#include "raytracer/render/integrators/path.hpp"
#include "raytracer/render/media/henyey_greenstein.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "raytracer/render/materials/texture.hpp"

namespace sweeptrace {

namespace {

// Sampler dimensions. Camera vertex j >= 1 (cam[j]) takes bounce slot 2j - 1 (its NEE light
// choice and point, lobe, direction, roulette at the path tracer's slot offsets); light vertex b
// (light[b]) takes bounce slot 2b: for b = 0 the emission (light choice and part, point,
// direction), for b >= 1 lobe, direction, roulette; every light vertex's lens point for t = 1
// sits at slot offset kLens. Interleaved, so neither subpath's length moves the other's numbers.
int camera_slot(int j, int slot) { return sample_dim::bounce(2 * j - 1, slot); }
int light_slot(int b, int slot) { return sample_dim::bounce(2 * b, slot); }
constexpr int kLensSlot = 9;  // 2D, past the path tracer's guiding slot (8)
// The subpaths' own random streams for free flights and transmittance (PixelSampler::stream;
// the path tracer's is 1), apart from each other so neither replays the other's distances.
constexpr std::uint64_t kCameraMediumStream = 2, kLightMediumStream = 3;

// A vertex as one end of a ray: a medium point has no surface to step off (its error is 0), so
// its stand-in normal is the direction to the other end, which keeps spawn_ray_to's margins
// those of a head-on target.
SurfaceHit ray_end(const SurfaceHit& hit, bool in_medium, const glm::vec3& toward) {
    if (!in_medium) return hit;
    SurfaceHit p;
    p.point = hit.point;
    p.normal = p.shading_normal = toward;
    p.object = LightSet::kNoObject;
    return p;
}

// The phase function as a medium vertex's "BSDF": no cosine, and symmetric, so its density of
// the reverse direction is the same value.
BsdfEvalBoth eval_phase(float g, const glm::vec3& wo, const glm::vec3& wi) {
    const float p = hg_phase(glm::dot(-wo, wi), g);
    return {glm::vec3(p), p, p};
}

// pbrt's adjoint correction for shading normals, on a light subpath: light arrives along wo and
// leaves along wi, the BSDF's f |wi.ns| then times |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|).
float shading_correction(const SurfaceHit& hit, const glm::vec3& wo, const glm::vec3& wi) {
    const float den = std::abs(glm::dot(wo, hit.normal)) * std::abs(glm::dot(wi, hit.shading_normal));
    if (!(den > 0.0f)) return 0.0f;
    return std::abs(glm::dot(wo, hit.shading_normal)) * std::abs(glm::dot(wi, hit.normal)) / den;
}

// The textured material of a surface vertex, stored in it (the hit's shading normal may change).
void set_material(const Scene& scene, PathVertex& v) {
    v.material = scene.objects[v.hit.object].material;
    const MaterialParameters& base = scene.materials[v.material];
    v.has_textured = reads_texture(base);
    if (v.has_textured) v.textured = textured_material(scene, base, v.hit);
}

// The medium each light emits into, for the lights where it can be found once per render
// rather than by a probe ray on every light subpath (light_walk): a point or spot light's, whose
// position is fixed, found by probes from it in eight directions (+-1, +-2, +-3), one per
// octant, when they all agree. Not when a boundary moves during the shutter (where the light is
// then depends on the sample's time), nor when the probes disagree (a light on a boundary, or
// boundaries that do not close around it): those lights, surface lights (their point varies) and
// lights at infinity keep the probe along each light subpath's first ray.
std::vector<std::int32_t> light_media(const Scene& scene, const Accel& accel, const LightSet& lights, bool moving,
                                      std::int32_t probe_each_sample) {
    std::vector<std::int32_t> out(static_cast<std::size_t>(lights.light_count()), probe_each_sample);
    for (const Object& o : scene.objects)
        if (o.media.transition() && scene.camera.shutter && o.motion.moving()) return out;
    for (std::uint32_t l = 0; l < out.size(); ++l) {
        if (!lights.light_is_delta_position(l)) continue;
        std::int32_t found = probe_each_sample;
        for (int octant = 0; octant < 8; ++octant) {
            const glm::vec3 dir = glm::normalize(glm::vec3(octant & 1 ? -1.0f : 1.0f, octant & 2 ? -2.0f : 2.0f,
                                                           octant & 4 ? -3.0f : 3.0f));
            std::uint64_t rays = 0;
            const std::int32_t m = medium_at(accel, scene, collision::Ray{lights.delta_light_position(l), dir, 0.0f,
                                                                          std::numeric_limits<float>::infinity()},
                                             moving, 0.0f, rays);
            if (octant > 0 && m != found) {
                found = probe_each_sample;
                break;
            }
            found = m;
        }
        out[l] = found;
    }
    return out;
}

}  // namespace

struct BdptIntegrator::Subpaths {
    std::vector<PathVertex> cam, light;
    Rng cam_rng, light_rng;  // with media: each subpath's stream for flights and its connections' transmittance
    LightVertices stored;  // bdpt's own sample: the light subpath's vertices that connect
    MisPath mis;
    float merge_eta = 0.0f;  // the merging density the weights count (vcm's, per iteration), 0 for bdpt
};

BdptIntegrator::BdptIntegrator(const Scene& scene, const Accel& accel, const LightSet& lights,
                               const CameraModel& camera, int max_depth, PlantedDefect defect, RoulettePolicy roulette,
                               bool light_tracing_only)
    : scene_(scene),
      accel_(accel),
      lights_(lights),
      camera_(camera),
      max_depth_(max_depth),
      defect_(defect),
      roulette_(roulette),
      light_tracing_only_(light_tracing_only),
      filter_radius_(scene.film.filter.radius),
      media_(scene) {
    for (const Object& o : scene.objects) moving_ = moving_ || (scene.camera.shutter && o.motion.moving());
    for (std::uint32_t l = 0; l < static_cast<std::uint32_t>(lights.light_count()); ++l)
        if (lights.light_is_found_at_infinity(l)) infinite_lights_.push_back(l);
    if (media_.active()) light_medium_ = light_media(scene, accel, lights, moving_, kProbeEachSample);
}

bool BdptIntegrator::blocked(const collision::Ray& ray, float time) const {
    return moving_ ? accel_.occluded(ray, time) : accel_.occluded(ray);
}

BsdfEvalBoth BdptIntegrator::eval_at(const PathVertex& v, const glm::vec3& wi) const {
    if (v.in_medium()) return eval_phase(media_.model(v.medium).g(), v.wo, wi);
    return eval_bsdf_both(v.mat(scene_), v.hit, v.wo, wi);
}

std::int32_t BdptIntegrator::medium_leaving(const PathVertex& v, const glm::vec3& dir) const {
    if (v.on_surface() && v.hit.object < scene_.objects.size())
        return media_.after_crossing(v.hit.object, v.hit.normal, dir, v.medium);
    return v.medium;
}

template <class Next>
SegmentTransmittance BdptIntegrator::joined(const collision::Ray& ray, std::int32_t medium, float time, Rng& rng,
                                            std::uint64_t& rays, Next&& next) const {
    if (!media_.active()) return {blocked(ray, time) ? glm::vec3(0.0f) : glm::vec3(1.0f), glm::vec3(1.0f)};
    return segment_transmittance(media_, accel_, ray, medium, moving_, time, rng, rays, next);
}

MisDefect BdptIntegrator::mis_defect() const {
    return defect_ == PlantedDefect::BdptDropsNee     ? MisDefect::DropNee
           : defect_ == PlantedDefect::VcmDropsMerges ? MisDefect::DropMerges
                                                      : MisDefect::None;
}

float BdptIntegrator::weight(const MisPath& path, int s, float merge_eta) const {
    if (light_tracing_only_) return 1.0f;
    return mis_weight(path, s, false, merge_eta, mis_defect());
}

glm::vec3 BdptIntegrator::sample(float x, float y, const glm::vec2& lens, float time, PixelSampler& sampler,
                                 std::uint64_t& rays, std::vector<Splat>& splats, SampleFeatures* features) const {
    thread_local Subpaths sp;
    glm::vec3 l(0.0f);
    if (features != nullptr) *features = SampleFeatures{};  // light tracing alone: no camera subpath, a miss
    sp.merge_eta = 0.0f;
    if (light_tracing_only_) {
        light_walk(time, sampler, rays, sp);
        for (int s = 1; s <= static_cast<int>(sp.light.size()) && s <= max_depth_ && !cancelled(); ++s)
            light_to_camera(sp, s, time, sampler, rays, splats);
        return l;
    }
    camera_walk(x, y, lens, time, sampler, rays, sp, l);
    if (features != nullptr) *features = features_of_subpath(scene_, sp.cam, camera_);
    light_walk(time, sampler, rays, sp);
    sp.stored.clear();
    store_light_vertices(sp, sp.stored);
    l += connections(sp, sp.stored, 0, sp.stored.size(), time, sampler, rays);
    const int nl = static_cast<int>(sp.light.size());
    for (int s = 1; s <= nl && s <= max_depth_ && !cancelled(); ++s) light_to_camera(sp, s, time, sampler, rays, splats);
    return l;
}

// Every strategy with t >= 2: emitters found (s = 0), next event estimation (s = 1), connections
// to the stored light vertices [first, first + count) of one light subpath (in depth order).
glm::vec3 BdptIntegrator::connections(Subpaths& sp, const LightVertices& light, std::size_t first, std::size_t count,
                                      float time, PixelSampler& sampler, std::uint64_t& rays) const {
    glm::vec3 l(0.0f);
    const int nc = static_cast<int>(sp.cam.size());
    for (int t = 2; t <= nc && !cancelled(); ++t) {
        const int j = t - 1;
        if (!sp.cam[j].in_medium()) {
            l += emitter_hit(sp, j);
            if (!scatters(sp.cam[j].mat(scene_)) || is_delta(sp.cam[j].mat(scene_))) continue;
        }
        if (j + 1 <= max_depth_) l += next_event(sp, j, time, sampler, rays);
        for (std::size_t i = first; i < first + count; ++i) {
            if (light.photon(i).mis.depth + t > max_depth_) break;  // s + t - 1 vertices after the light
            l += connect(sp, light, i, t, time, rays);
        }
    }
    return l;
}

// The walk's vertices that a later technique can end at (light_vertices.hpp).
void BdptIntegrator::store_light_vertices(const Subpaths& sp, LightVertices& out) const {
    for (std::size_t b = 1; b < sp.light.size(); ++b) {
        const PathVertex& v = sp.light[b];
        if (!media_.active()) {
            if (!is_delta(v.mat(scene_))) out.push(v);
        } else if (v.in_medium()) {
            out.push(v, v.medium, v.medium);
        } else if (!is_delta(v.mat(scene_))) {
            // A boundary's two media; any other surface has the medium its subpath arrived in on both.
            const MediumInterface& mi = scene_.objects[v.hit.object].media;
            const bool boundary = mi.transition();
            out.push(v, boundary ? mi.outside : v.medium, boundary ? mi.inside : v.medium);
        }
    }
}

void BdptIntegrator::light_subpath(float time, PixelSampler& sampler, std::uint64_t& rays, float merge_eta,
                                   LightVertices& light, std::vector<Splat>& splats) const {
    thread_local Subpaths sp;
    sp.merge_eta = merge_eta;
    light_walk(time, sampler, rays, sp);
    const int nl = static_cast<int>(sp.light.size());
    for (int s = 1; s <= nl && s <= max_depth_ && !cancelled(); ++s) light_to_camera(sp, s, time, sampler, rays, splats);
    store_light_vertices(sp, light);
}

glm::vec3 BdptIntegrator::camera_subpath(float x, float y, const glm::vec2& lens, float time, PixelSampler& sampler,
                                         std::uint64_t& rays, const LightVertices& light, std::size_t first,
                                         std::size_t count, float merge_eta, std::vector<PathVertex>& cam,
                                         SampleFeatures* features) const {
    thread_local Subpaths sp;
    sp.merge_eta = merge_eta;
    glm::vec3 l(0.0f);
    camera_walk(x, y, lens, time, sampler, rays, sp, l);
    if (features != nullptr) *features = features_of_subpath(scene_, sp.cam, camera_);
    l += connections(sp, light, first, count, time, sampler, rays);
    std::swap(cam, sp.cam);
    return l;
}

void BdptIntegrator::camera_walk(float x, float y, const glm::vec2& lens, float time, PixelSampler& sampler,
                                 std::uint64_t& rays, Subpaths& sp, glm::vec3& found) const {
    sp.cam.clear();
    PathVertex c;
    c.kind = PathVertex::Kind::Camera;
    c.hit.point = camera_.lens_point(lens.x, lens.y);
    c.medium = scene_.camera.medium;
    sp.cam.push_back(c);
    collision::Ray ray = camera_.generate(x, y, lens.x, lens.y);
    float pdf = camera_.direction_pdf(glm::dot(ray.dir, camera_.forward()));
    glm::vec3 beta(1.0f);
    float eta_scale = 1.0f;
    std::int32_t medium = scene_.camera.medium;
    if (media_.active()) sp.cam_rng = sampler.stream(kCameraMediumStream);
    for (int depth = 1;; ++depth) {
        PathVertex v;
        ++rays;
        if (!next_vertex(ray, medium, time, sp.cam_rng, rays, beta, v, &found)) {
            found += escaped_radiance(sp, ray.dir, beta, pdf, v.mis_tr);
            return;
        }
        v.beta = beta;
        medium = v.medium;  // where the flight ended (it may have crossed interfaces)
        v.pdf_own = area_density(pdf, sp.cam.back().point(), v) * flight_density(v.mis_tr, v);
        sp.cam.push_back(std::move(v));
        sp.cam.back().above = camera_vertex_above(sp.cam, depth, sp.merge_eta, mis_defect());
        const PathVertex& at = sp.cam.back();
        if (depth >= max_depth_) return;
        PathVertex& prev = sp.cam[static_cast<std::size_t>(depth - 1)];
        if (at.in_medium()) {
            // The phase function's sample: its weight p / pdf is 1, its reverse density the same p.
            const glm::vec2 b = sampler.get2d(camera_slot(depth, sample_dim::kBsdfDirection));
            const glm::vec3 wi = hg_sample(-at.wo, media_.model(at.medium).g(), b.x, b.y, pdf);
            if (depth >= 2) prev.pdf_other = area_density(pdf, at.point(), prev) * flight_density(at.mis_tr, prev);
            if (depth >= roulette_.start_depth &&
                !survives_roulette(roulette_, depth, sampler.get1d(camera_slot(depth, sample_dim::kRoulette)), eta_scale, beta))
                return;
            ray = collision::Ray{at.point(), wi, 0.0f, std::numeric_limits<float>::infinity()};
            continue;
        }
        const MaterialParameters& mat = at.mat(scene_);
        if (!scatters(mat)) return;
        const ShadingContext ctx = make_shading_context(at.hit, at.wo);
        const float b0 = sampler.get1d(camera_slot(depth, sample_dim::kBsdfLobe));
        const glm::vec2 b = sampler.get2d(camera_slot(depth, sample_dim::kBsdfDirection));
        BsdfSample bs;
        if (!sample_bsdf(mat, ctx, b0, b.x, b.y, bs)) return;
        const float rev = bs.delta ? 0.0f : eval_bsdf(mat, make_shading_context(at.hit, bs.wi), at.wo).pdf;
        if (depth >= 2) prev.pdf_other = area_density(rev, at.point(), prev) * flight_density(at.mis_tr, prev);
        sp.cam.back().delta = bs.delta;
        pdf = bs.delta ? 0.0f : bs.pdf;
        beta *= bs.weight;
        const bool refracting = mat.type == Material::Type::Dielectric || mat.type == Material::Type::RoughDielectric;
        if (refracting && glm::dot(bs.wi, ctx.ng) < 0.0f) {
            const float eta = ctx.front ? mat.ior : 1.0f / mat.ior;
            eta_scale *= eta * eta;
        }
        if (depth >= roulette_.start_depth &&
            !survives_roulette(roulette_, depth, sampler.get1d(camera_slot(depth, sample_dim::kRoulette)), eta_scale, beta))
            return;
        if (media_.active()) medium = media_.after_crossing(at.hit.object, at.hit.normal, bs.wi, medium);
        ray = spawn_ray(at.hit, bs.wi);
    }
}

// The subpath's next vertex along `ray` (traced in `medium`): a surface, or with media a medium
// vertex where the free flight scattered (the flight's weight taken into `beta`). False when
// the ray escapes (v.mis_tr then holds the flight's MIS transmittance). With `emitted` (the
// camera subpath), the emission of the media the flight crossed, times the throughput before it,
// is added there at full weight: no other strategy makes a path that ends in a medium.
bool BdptIntegrator::next_vertex(const collision::Ray& ray, std::int32_t medium, float time, Rng& rng,
                                 std::uint64_t& rays, glm::vec3& beta, PathVertex& v, glm::vec3* emitted) const {
    if (media_.active()) {
        const FlightEnd fe = fly(media_, accel_, ray, medium, moving_, time, rng, rays, emitted != nullptr);
        if (emitted != nullptr) *emitted += beta * fe.emitted;
        beta *= fe.weight;
        v.mis_tr = fe.mis_tr;
        if (fe.kind == FlightEnd::Kind::Escaped) return false;
        v.hit = fe.hit;
        v.medium = fe.medium;
        v.sigma_t = fe.sigma_t;
        v.kind = fe.kind == FlightEnd::Kind::Medium ? PathVertex::Kind::Medium : PathVertex::Kind::Surface;
    } else if (!(moving_ ? accel_.intersect(ray, time, v.hit) : accel_.intersect(ray, v.hit))) {
        return false;
    }
    v.wo = -ray.dir;
    if (!v.in_medium()) set_material(scene_, v);
    return true;
}

void BdptIntegrator::light_walk(float time, PixelSampler& sampler, std::uint64_t& rays, Subpaths& sp) const {
    sp.light.clear();
    if (lights_.empty()) return;
    const glm::vec2 uc = sampler.get2d(light_slot(0, sample_dim::kLightChoice));
    const glm::vec2 up = sampler.get2d(light_slot(0, sample_dim::kLightPoint));
    const glm::vec2 ud = sampler.get2d(light_slot(0, sample_dim::kBsdfDirection));
    LightEmission em;
    if (!lights_.sample_emission(uc.x, uc.y, up.x, up.y, ud.x, ud.y, em)) return;
    PathVertex v0;
    v0.kind = PathVertex::Kind::Light;
    v0.hit.point = em.point;
    v0.hit.point_error = em.point_error;
    v0.hit.normal = v0.hit.shading_normal = em.normal;
    v0.hit.object = em.object;
    v0.hit.primitive = em.primitive;
    v0.light = em.light;
    v0.at_infinity = em.at_infinity;
    v0.delta_position = em.delta_position;
    v0.delta_direction = em.delta_direction;
    v0.beta = glm::vec3(1.0f / (em.selection * em.pdf_pos));
    v0.pdf_own = em.selection * (em.at_infinity ? em.pdf_dir : em.pdf_pos);
    const bool light_hittable =
        !v0.delta_position && !v0.delta_direction && (!v0.at_infinity || lights_.light_is_found_at_infinity(v0.light));
    v0.light_mis = light_origin_mis(v0, light_hittable);
    sp.light.push_back(v0);
    const float cos0 = v0.on_surface() ? std::abs(glm::dot(em.normal, em.dir)) : 1.0f;
    glm::vec3 beta = em.le * (cos0 / (em.selection * em.pdf_pos * em.pdf_dir));
    const float beta_start = max_component(beta);
    collision::Ray ray;
    if (v0.on_surface()) {
        ray = spawn_ray(v0.hit, em.dir);
    } else {
        ray.origin = em.point;
        ray.dir = em.dir;
        ray.tmin = 0.0f;
    }
    std::int32_t medium = -1;
    if (media_.active()) {
        // The medium the light emits into: its boundary's side, else the one found at setup,
        // else found from around it along this ray.
        sp.light_rng = sampler.stream(kLightMediumStream);
        const bool boundary = em.object < scene_.objects.size() && scene_.objects[em.object].media.transition();
        medium = boundary                                   ? media_.after_crossing(em.object, em.normal, em.dir, -1)
                 : light_medium_[em.light] != kProbeEachSample ? light_medium_[em.light]
                                                             : medium_at(accel_, scene_, ray, moving_, time, rays);
        sp.light.back().medium = medium;
    }
    float pdf = em.pdf_dir;
    for (int b = 1; b < max_depth_; ++b) {
        PathVertex v;
        ++rays;
        if (!next_vertex(ray, medium, time, sp.light_rng, rays, beta, v)) return;
        v.beta = beta;
        medium = v.medium;  // where the flight ended (it may have crossed interfaces)
        PathVertex& prev = sp.light.back();
        const float cos_v = v.in_medium() ? 1.0f : std::abs(glm::dot(v.hit.normal, ray.dir));
        v.pdf_own = (prev.at_infinity ? em.pdf_pos * cos_v : area_density(pdf, prev.point(), v)) * flight_density(v.mis_tr, v);
        if (b == 1) {
            // Next event estimation's density of the light point from here, for strategy s = 1.
            PathVertex& l0 = sp.light.front();
            if (l0.at_infinity || l0.delta_position) {
                // At infinity: NEE's density from v, not emission's (they differ under a portal).
                l0.pdf_nee = l0.at_infinity ? lights_.nee_density_of_light(l0.light, v.point(), -em.dir) : em.selection;
            } else {
                l0.pdf_nee = area_density(lights_.pdf(v.point(), v.hit.object, l0.hit), v.point(), l0);
            }
            l0.light_mis.nee0 = l0.pdf_nee;
        }
        if (!v.in_medium() && !scatters(v.mat(scene_))) return;  // an absorber: every connection through it is zero
        sp.light.push_back(std::move(v));
        sp.light.back().light_mis = light_vertex_mis(sp.light, b, light_hittable, sp.merge_eta, mis_defect());
        PathVertex& at = sp.light.back();
        if (b + 1 >= max_depth_) return;
        PathVertex& before = sp.light[static_cast<std::size_t>(b - 1)];
        if (at.in_medium()) {
            const glm::vec2 bd = sampler.get2d(light_slot(b, sample_dim::kBsdfDirection));
            const glm::vec3 wi = hg_sample(-at.wo, media_.model(at.medium).g(), bd.x, bd.y, pdf);
            before.pdf_other = area_density(pdf, at.point(), before) * flight_density(at.mis_tr, before);
            if (!light_roulette(sampler, b, beta, beta_start)) return;
            ray = collision::Ray{at.point(), wi, 0.0f, std::numeric_limits<float>::infinity()};
            continue;
        }
        const ShadingContext ctx = make_shading_context(at.hit, at.wo);
        const float b0 = sampler.get1d(light_slot(b, sample_dim::kBsdfLobe));
        const glm::vec2 bd = sampler.get2d(light_slot(b, sample_dim::kBsdfDirection));
        BsdfSample bs;
        if (!sample_bsdf(at.mat(scene_), ctx, b0, bd.x, bd.y, bs)) return;
        beta *= bs.weight * (importance_refraction_scale(at.mat(scene_), ctx, bs.wi) * shading_correction(at.hit, at.wo, bs.wi));
        const float rev = bs.delta ? 0.0f : eval_bsdf(at.mat(scene_), make_shading_context(at.hit, bs.wi), at.wo).pdf;
        before.pdf_other = area_density(rev, at.point(), before) * flight_density(at.mis_tr, before);
        at.delta = bs.delta;
        pdf = bs.delta ? 0.0f : bs.pdf;
        if (!light_roulette(sampler, b, beta, beta_start)) return;
        if (media_.active()) medium = media_.after_crossing(at.hit.object, at.hit.normal, bs.wi, medium);
        ray = spawn_ray(at.hit, bs.wi);
    }
}

// Roulette on a light subpath's throughput relative to its first segment's (it carries power).
bool BdptIntegrator::light_roulette(PixelSampler& sampler, int b, glm::vec3& beta, float beta_start) const {
    if (b < roulette_.start_depth) return true;
    const float q = std::min(1.0f, max_component(beta) / beta_start);
    if (!(sampler.get1d(light_slot(b, sample_dim::kRoulette)) < q)) return false;
    beta /= q;
    return true;
}

// s = 0 at infinity: the camera subpath escaped along `dir` from its last vertex, sampled with
// solid-angle density `pdf` there, its flight's MIS transmittance `mis_tr` (1 in vacuum). A
// background that is no light has no other strategy.
glm::vec3 BdptIntegrator::escaped_radiance(const Subpaths& sp, const glm::vec3& dir, const glm::vec3& beta, float pdf,
                                           const glm::vec3& mis_tr) const {
    glm::vec3 sum(0.0f);
    if (!lights_.background_is_light()) sum += beta * background_radiance(scene_.background, dir);
    if (infinite_lights_.empty()) return sum;
    const int k = static_cast<int>(sp.cam.size());  // the light is x_0, cam.back() is x_1
    const int j = k - 1;
    MisPath m;
    m.reset(k, 0, std::min(k, 3));
    m.fc(0) = pdf * flight_density(mis_tr, glm::vec3(0.0f), false);
    m.light_to_camera = false;
    const PathVertex& x1 = sp.cam.back();
    // x_2's density from x_1 is the walk's: x_1 sampled the escaping direction.
    const float fl2 = j >= 2 ? sp.cam[static_cast<std::size_t>(j - 1)].pdf_other : 0.0f;
    for (const std::uint32_t light : infinite_lights_) {
        const glm::vec3 le = lights_.radiance_at_infinity(light, dir);
        if (!(luminance(le) > 0.0f)) continue;
        const LightSet::EmissionDensity d = lights_.emission_density(light, -dir, -dir);
        m.emit0 = d.pos;
        m.nee0 = lights_.nee_density_of_light(light, x1.point(), dir);  // emission's and NEE's differ under a portal
        const float cos1 = x1.in_medium() ? 1.0f : std::abs(glm::dot(x1.hit.normal, dir));
        const float fl1 = k >= 2 ? d.dir * cos1 * flight_density(mis_tr, x1) : 0.0f;
        put_camera_end(m, sp.cam, j, 1, fl1, fl2, true);
        sum += beta * le * weight(m, 0, sp.merge_eta);
    }
    return sum;
}

// s = 0 on a surface: cam[j] is on an emitter.
glm::vec3 BdptIntegrator::emitter_hit(Subpaths& sp, int j) const {
    const PathVertex& z = sp.cam[static_cast<std::size_t>(j)];
    const glm::vec3 le = emitted_radiance(z.mat(scene_), z.hit.normal, z.wo);
    if (le == glm::vec3(0.0f)) return le;
    if (!lights_.is_light(z.hit.object)) return z.beta * le;  // no light sampling finds it
    MisPath& m = sp.mis;
    m.reset(j, 0, std::min(j, 2));
    const auto light = static_cast<std::uint32_t>(lights_.light_of_object(z.hit.object));  // an emitter: is_light
    const LightSet::EmissionDensity d = lights_.emission_density(light, z.hit.normal, z.wo);
    m.emit0 = d.pos;
    m.nee0 = d.pos;
    float fl1 = 0.0f;
    if (j >= 2) {
        const PathVertex& x1 = sp.cam[static_cast<std::size_t>(j - 1)];
        fl1 = area_density(d.dir, z.point(), x1) * flight_density(z.mis_tr, x1);
        m.nee0 = area_density(lights_.pdf(x1.point(), x1.hit.object, z.hit), x1.point(), z.point(), z.hit.normal);
    }
    m.light_hittable = true;
    m.light_to_camera = true;
    put_camera_end(m, sp.cam, j, 0, 0.0f, fl1);
    return z.beta * le * weight(m, 0, sp.merge_eta);
}

// s = 1: next event estimation from cam[j], as the path tracer draws it.
glm::vec3 BdptIntegrator::next_event(Subpaths& sp, int j, float time, PixelSampler& sampler,
                                     std::uint64_t& rays) const {
    const PathVertex& z = sp.cam[static_cast<std::size_t>(j)];
    const glm::vec2 uc = sampler.get2d(camera_slot(j, sample_dim::kLightChoice));
    const glm::vec2 u = sampler.get2d(camera_slot(j, sample_dim::kLightPoint));
    LightSample ls;
    if (!lights_.sample(z.point(), z.hit.object, uc.x, uc.y, u.x, u.y, ls)) return glm::vec3(0.0f);
    const BsdfEvalBoth e = eval_at(z, ls.wi);
    if (!(e.pdf_wi > 0.0f)) return glm::vec3(0.0f);
    glm::vec3 c = z.beta * e.f_cos * ls.radiance / ls.pdf;
    if (!(max_component(c) > 0.0f)) return glm::vec3(0.0f);
    ++rays;
    const SurfaceHit from = ray_end(z.hit, z.in_medium(), ls.wi);
    const auto toward_light = [&](const SurfaceHit& h) {
        return ls.at_infinity ? spawn_ray(h, ls.wi) : spawn_ray_to(h, ls.point, ls.point_error, ls.normal);
    };
    const SegmentTransmittance tr = joined(toward_light(from), medium_leaving(z, ls.wi), time, sp.cam_rng, rays, toward_light);
    if (tr.tr == glm::vec3(0.0f)) return glm::vec3(0.0f);
    c *= tr.tr;
    // The light point as a path vertex x_0, and the path's densities.
    const std::uint32_t light = lights_.light_of_sample(uc.x);
    PathVertex x0;
    x0.kind = PathVertex::Kind::Light;
    x0.hit.point = ls.point;
    x0.hit.normal = ls.normal;
    x0.light = light;
    x0.at_infinity = ls.at_infinity;
    x0.delta_position = lights_.light_is_delta_position(light);
    x0.delta_direction = ls.delta && ls.at_infinity;
    const LightSet::EmissionDensity d = lights_.emission_density(light, ls.normal, -ls.wi);
    MisPath& m = sp.mis;
    const int k = j + 1;
    m.reset(k, 0, std::min(k, 3));
    m.emit0 = d.pos;
    m.nee0 = ls.at_infinity || x0.delta_position ? ls.pdf : area_density(ls.pdf, z.point(), x0);
    m.light_hittable = !x0.delta_position && !x0.delta_direction &&
                       (!x0.at_infinity || lights_.light_is_found_at_infinity(light));
    m.light_to_camera = !x0.at_infinity;
    m.fc(0) = area_density(e.pdf_wi, z.point(), x0) * flight_density(tr.mis_tr, x0);
    const float cos_z = z.in_medium() ? 1.0f : std::abs(glm::dot(z.hit.normal, ls.wi));
    const float fl1 = (ls.at_infinity ? d.dir * cos_z : area_density(d.dir, ls.point, z)) * flight_density(tr.mis_tr, z);
    const PathVertex& z_next = sp.cam[static_cast<std::size_t>(j - 1)];
    const float fl2 = j >= 2 ? area_density(e.pdf_wo, z.point(), z_next) * flight_density(z.mis_tr, z_next) : 0.0f;
    put_camera_end(m, sp.cam, j, 1, fl1, fl2);
    return c * weight(m, 1, sp.merge_eta);
}

// s >= 2, t >= 2: the stored light vertex `i` (x_{s-1}) joined to cam[t-1] by a shadow ray.
glm::vec3 BdptIntegrator::connect(Subpaths& sp, const LightVertices& light, std::size_t i, int t, float time,
                                  std::uint64_t& rays) const {
    const Photon& yp = light.photon(i);
    const SurfaceHit yhit = light.hit(i);
    const bool y_medium = light.in_medium(i);
    const int j = t - 1, b = yp.mis.depth, s = b + 1;
    const PathVertex& z = sp.cam[static_cast<std::size_t>(j)];
    glm::vec3 w = z.point() - yp.point;
    const float d2 = glm::dot(w, w);
    if (!(d2 > 0.0f)) return glm::vec3(0.0f);
    w /= std::sqrt(d2);
    const std::int32_t y_side = y_medium || media_.active() ? light.medium_toward(i, w) : -1;
    BsdfEvalBoth ey;
    float fy_scale = 1.0f;
    if (y_medium) {
        ey = eval_phase(media_.model(y_side).g(), yp.wo, w);
    } else {
        const MaterialParameters& my = light.material(i, scene_);
        ey = eval_bsdf_both(my, yhit, yp.wo, w);
        fy_scale = importance_refraction_scale(my, make_shading_context(yhit, yp.wo), w) * shading_correction(yhit, yp.wo, w);
    }
    if (!(ey.pdf_wi > 0.0f)) return glm::vec3(0.0f);
    const BsdfEvalBoth ez = eval_at(z, -w);
    if (!(ez.pdf_wi > 0.0f)) return glm::vec3(0.0f);
    glm::vec3 c = yp.beta * ey.f_cos * fy_scale * ez.f_cos * z.beta / d2;
    if (!(max_component(c) > 0.0f)) return glm::vec3(0.0f);
    ++rays;
    const SurfaceHit to = ray_end(z.hit, z.in_medium(), -w);
    const auto toward_z = [&](const SurfaceHit& h) { return spawn_ray_to(h, to.point, to.point_error, to.normal); };
    const SegmentTransmittance tr = joined(toward_z(ray_end(yhit, y_medium, w)), y_side, time, sp.cam_rng, rays, toward_z);
    if (tr.tr == glm::vec3(0.0f)) return glm::vec3(0.0f);
    c *= tr.tr;
    MisPath& m = sp.mis;
    const int k = s + j;
    m.reset(k, b - 1, std::min(k, s + 2));
    put_light_end(m, yp.mis, ey.pdf_wo);
    // y as the camera's direction reaches it (no cosine at a medium vertex), over the joining segment.
    const glm::vec3 y_sigma_t = y_medium ? extinction(y_side, yp.point) : glm::vec3(0.0f);
    m.fc(b) = (y_medium ? ez.pdf_wi / d2 : area_density(ez.pdf_wi, z.point(), yp.point, yp.normal)) *
              flight_density(tr.mis_tr, y_sigma_t, y_medium);
    const PathVertex& z_next = sp.cam[static_cast<std::size_t>(j - 1)];
    const float fl_next = j >= 2 ? area_density(ez.pdf_wo, z.point(), z_next) * flight_density(z.mis_tr, z_next) : 0.0f;
    put_camera_end(m, sp.cam, j, s, area_density(ey.pdf_wi, yp.point, z) * flight_density(tr.mis_tr, z), fl_next);
    return c * weight(m, s, sp.merge_eta);
}

// t = 1: light[s-1] joined to a point on the lens, splatted where it lands on the film.
void BdptIntegrator::light_to_camera(Subpaths& sp, int s, float time, PixelSampler& sampler, std::uint64_t& rays,
                                     std::vector<Splat>& splats) const {
    const PathVertex& y = sp.light[static_cast<std::size_t>(s - 1)];
    if (y.kind == PathVertex::Kind::Light && (y.at_infinity || y.delta_direction)) return;
    if (y.kind == PathVertex::Kind::Surface && is_delta(y.mat(scene_))) return;  // a medium vertex never is
    const glm::vec2 ul = sampler.get2d(light_slot(s - 1, kLensSlot));
    const glm::vec3 lens = camera_.lens_point(ul.x, ul.y);
    float fx = 0.0f, fy = 0.0f;
    const float margin = std::max(0.0f, filter_radius_ - 0.5f);
    if (!camera_.film_position(lens, y.point(), margin, fx, fy)) return;
    glm::vec3 w = lens - y.point();
    const float d = glm::length(w);
    w /= d;
    const float cos_theta = -glm::dot(w, camera_.forward());
    const float importance = camera_.direction_pdf(cos_theta) / (d * d);
    glm::vec3 f(0.0f);
    BsdfEvalBoth ey;
    if (y.kind == PathVertex::Kind::Light) {
        f = lights_.emission_toward(y.light, y.point(), y.hit.normal, y.hit.primitive, w);
        if (y.on_surface()) f *= std::abs(glm::dot(y.hit.normal, w));
    } else if (y.in_medium()) {
        ey = eval_at(y, w);
        f = ey.f_cos;
    } else {
        ey = eval_bsdf_both(y.mat(scene_), y.hit, y.wo, w);
        f = ey.f_cos * (importance_refraction_scale(y.mat(scene_), make_shading_context(y.hit, y.wo), w) *
                        shading_correction(y.hit, y.wo, w));
    }
    glm::vec3 c = y.beta * f * importance;
    if (!(max_component(c) > 0.0f)) return;
    // The shadow ray stops at the near clip plane: nothing between it and the lens is seen.
    const float to_clip = camera_.near_clip() / cos_theta;
    const glm::vec3 target = lens - w * to_clip;
    ++rays;
    collision::Ray shadow;
    if (y.on_surface() || y.kind == PathVertex::Kind::Surface) {
        shadow = spawn_ray_to(y.hit, target, glm::vec3(0.0f), w);
    } else {
        shadow.origin = y.point();
        shadow.dir = target - y.point();
        shadow.tmin = 0.0f;
        shadow.tmax = 1.0f;  // the far end is the lens or the clip plane: no surface to stop short of
    }
    const SegmentTransmittance tr = joined(shadow, medium_leaving(y, w), time, sp.light_rng, rays, [&](const SurfaceHit& h) {
        return spawn_ray_to(h, target, glm::vec3(0.0f), w);
    });
    if (tr.tr == glm::vec3(0.0f)) return;
    c *= tr.tr;
    // The path light[0..s) + the lens point x_k, k = s (whose densities count nowhere: t = 0 is
    // impossible).
    MisPath& m = sp.mis;
    const int b = s - 1;
    m.reset(s, std::max(0, b - 1), s);
    put_light_end(m, y.light_mis, ey.pdf_wo);
    m.fc(b) = area_density(camera_.direction_pdf(cos_theta), lens, y) * flight_density(tr.mis_tr, y);
    m.light_to_camera = !sp.light.front().at_infinity;
    const glm::vec3 value = c * weight(m, s, sp.merge_eta);
    // One splat at the film point: the renderer spreads it over the pixels its filter reaches
    // (film_splats.hpp), so a wide filter costs no more memory than a narrow one.
    splats.push_back({glm::vec2(fx, fy), value});
}

}  // namespace sweeptrace

#include "raytracer/render/integrators/vcm.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "raytracer/render/bsdf.hpp"
#include "raytracer/render/integrators/vcm_mis.hpp"
#include "raytracer/render/lights.hpp"
#include "raytracer/render/sampling.hpp"

namespace sweeptrace {

VcmIntegrator::VcmIntegrator(const Scene& scene, const Accel& accel, const CameraModel& camera, const LightSet& lights,
                             BdptIntegrator& bdpt, int max_depth)
    : scene_(scene), lights_(lights), bdpt_(bdpt), max_depth_(max_depth), r1_(first_radius(scene, accel, camera)) {
    for (const Object& o : scene.objects) merging_ = merging_ && !(scene.camera.shutter && o.motion.moving());
    paths_.resize(static_cast<std::size_t>(scene.film.width) * static_cast<std::size_t>(scene.film.height));
}

float VcmIntegrator::median_pixel_footprint(const Scene& scene, const Accel& accel, const CameraModel& camera) {
    constexpr int kGrid = 16;
    const float w = static_cast<float>(scene.film.width), h = static_cast<float>(scene.film.height);
    std::vector<float> footprints;
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            // Pixel centres spread over the film, and the neighbouring centre one pixel right:
            // the angle between their rays times the hit distance is the pixel's width there.
            const float x = std::floor((static_cast<float>(i) + 0.5f) * w / kGrid) + 0.5f;
            const float y = std::floor((static_cast<float>(j) + 0.5f) * h / kGrid) + 0.5f;
            const collision::Ray ray = camera.generate(x, y, 0.5f, 0.5f);
            const collision::Ray next = camera.generate(x + 1.0f, y, 0.5f, 0.5f);
            SurfaceHit hit;
            if (!accel.intersect(ray, 0.0f, hit)) continue;
            const float distance = glm::length(hit.point - ray.origin);  // at the hit, not t: dir need not be unit
            const float angle = std::acos(std::clamp(glm::dot(glm::normalize(ray.dir), glm::normalize(next.dir)), -1.0f, 1.0f));
            const float footprint = distance * angle;
            if (std::isfinite(footprint) && footprint > 0.0f) footprints.push_back(footprint);
        }
    if (footprints.empty()) return 0.0f;
    const auto mid = footprints.begin() + static_cast<std::ptrdiff_t>(footprints.size() / 2);
    std::nth_element(footprints.begin(), mid, footprints.end());
    return *mid;
}

float VcmIntegrator::first_radius(const Scene& scene, const Accel& accel, const CameraModel& camera) {
    if (scene.film.vcm_radius > 0.0f) return scene.film.vcm_radius;
    const float footprint = median_pixel_footprint(scene, accel, camera);
    if (footprint > 0.0f) return kDefaultPixelFootprints * footprint;
    // Nothing seen: photons never meet a camera vertex that matters; any finite radius will do.
    const collision::Bounds3 world = scene_world_bounds(scene);
    const float r = world.empty() ? 1.0f : 0.5f * glm::length(world.hi - world.lo);
    return 0.003f * (std::isfinite(r) && r > 0.0f ? r : 1.0f);
}

float VcmIntegrator::radius(int iteration) const {
    return r1_ * std::pow(static_cast<float>(iteration) + 1.0f, 0.5f * (kAlpha - 1.0f));
}

void VcmIntegrator::begin_iteration(int iteration) {
    radius_ = radius(iteration);
    eta_ = merging_ ? kPi * radius_ * radius_ * static_cast<float>(paths_.size()) : 0.0f;
    bdpt_.set_merge_density(eta_);
}

void VcmIntegrator::trace_light(std::size_t pixel, float time, PixelSampler& sampler, std::uint64_t& rays,
                                std::vector<Splat>& splats) {
    bdpt_.light_subpath(time, sampler, rays, paths_[pixel], splats);
}

void VcmIntegrator::build_grid() {
    photons_.clear();
    grid_ = collision::HashedGrid<>(2.0f * radius_);
    if (!(eta_ > 0.0f)) return;
    for (std::size_t p = 0; p < paths_.size(); ++p) {
        const std::vector<PathVertex>& path = paths_[p];
        for (std::size_t b = 1; b < path.size(); ++b) {
            const PathVertex& v = path[b];
            if (v.kind != PathVertex::Kind::Surface || is_delta(v.mat(scene_))) continue;
            const auto id = static_cast<std::uint32_t>(photons_.size());
            photons_.push_back({v.point(), static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(b)});
            grid_.insert(id, v.point(), v.point());
        }
    }
}

glm::vec3 VcmIntegrator::sample(std::size_t pixel, float x, float y, const glm::vec2& lens, float time,
                                PixelSampler& sampler, std::uint64_t& rays, SampleFeatures* features) const {
    thread_local std::vector<PathVertex> cam;
    glm::vec3 l = bdpt_.camera_subpath(x, y, lens, time, sampler, rays, paths_[pixel], cam, features);
    if (!(eta_ > 0.0f)) return l;
    for (int j = 1; j < static_cast<int>(cam.size()) && j < max_depth_; ++j) {
        const Material& mat = cam[static_cast<std::size_t>(j)].mat(scene_);
        if (scatters(mat) && !is_delta(mat)) l += merge(cam, j);
    }
    return l;
}

// Merging at cam[j] = x_s with every photon (light[s] of some pixel's subpath) within the radius:
// the photon's power times the camera's f |wi.ns| / |wi.ng| (the photons carry power per unit
// geometric area), by the kernel 1 / (pi r^2) and 1 / N for the N light subpaths, so 1 / eta.
glm::vec3 VcmIntegrator::merge(const std::vector<PathVertex>& cam, int j) const {
    const PathVertex& z = cam[static_cast<std::size_t>(j)];
    const Material& mat = z.mat(scene_);
    const glm::vec3 r(radius_);
    const glm::ivec3 lo = grid_.cell_of(z.point() - r), hi = grid_.cell_of(z.point() + r);
    const float r2 = radius_ * radius_;
    thread_local MisPath m;
    glm::vec3 sum(0.0f);
    for (int cz = lo.z; cz <= hi.z; ++cz)
        for (int cy = lo.y; cy <= hi.y; ++cy)
            for (int cx = lo.x; cx <= hi.x; ++cx)
                for (const std::uint32_t id : grid_.cell(glm::ivec3(cx, cy, cz))) {
                    const Photon& ph = photons_[id];
                    const glm::vec3 d = ph.point - z.point();
                    if (glm::dot(d, d) > r2) continue;
                    const int s = static_cast<int>(ph.index), k = s + j;
                    if (k > max_depth_) continue;
                    const std::vector<PathVertex>& light = paths_[ph.pixel];
                    const PathVertex& y = light[ph.index];
                    const BsdfEvalBoth e = eval_bsdf_both(mat, z.hit, z.wo, y.wo);
                    const float cos_g = std::abs(glm::dot(y.wo, z.hit.normal));
                    if (!(e.pdf_wi > 0.0f) || !(cos_g > 0.0f)) continue;
                    const glm::vec3 c = z.beta * e.f_cos * y.beta / cos_g;
                    if (!(max_component(c) > 0.0f)) continue;
                    // The path light[0..s] + cam[j-1..0], x_s the camera's vertex.
                    m.k = k;
                    const auto n = static_cast<std::size_t>(k + 1);
                    m.fwd.assign(n, 0.0f);
                    m.rev.assign(n, 0.0f);
                    m.delta.assign(n, 0);
                    for (int i = 0; i < s; ++i) {
                        const PathVertex& v = light[static_cast<std::size_t>(i)];
                        m.fwd[static_cast<std::size_t>(i)] = v.pdf_fwd;
                        m.rev[static_cast<std::size_t>(i)] = v.pdf_rev;
                        m.delta[static_cast<std::size_t>(i)] = v.delta;
                    }
                    for (int i = s; i <= k; ++i) {
                        const PathVertex& v = cam[static_cast<std::size_t>(k - i)];
                        m.fwd[static_cast<std::size_t>(i)] = v.pdf_rev;
                        m.rev[static_cast<std::size_t>(i)] = v.pdf_fwd;
                        m.delta[static_cast<std::size_t>(i)] = v.delta;
                    }
                    m.fwd[static_cast<std::size_t>(s)] = y.pdf_fwd;
                    m.delta[static_cast<std::size_t>(s)] = 0;
                    m.rev[static_cast<std::size_t>(s - 1)] =
                        area_density(e.pdf_wi, z.point(), light[static_cast<std::size_t>(s - 1)]);
                    if (j >= 2) m.fwd[static_cast<std::size_t>(s + 1)] = area_density(e.pdf_wo, z.point(), cam[static_cast<std::size_t>(j - 1)]);
                    const PathVertex& l0 = light.front();
                    m.nee0 = l0.pdf_nee;
                    m.light_hittable = !l0.delta_position && !l0.delta_direction &&
                                       (!l0.at_infinity || lights_.light_is_found_at_infinity(l0.light));
                    m.light_to_camera = !l0.at_infinity;
                    sum += c * vcm_mis_weight(m, s, true, eta_, false);
                }
    return sum / eta_;
}

}  // namespace sweeptrace

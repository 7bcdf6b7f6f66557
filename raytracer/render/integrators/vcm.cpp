#include "raytracer/render/integrators/vcm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "raytracer/render/materials/bsdf.hpp"
#include "raytracer/render/integrators/bidir_mis.hpp"
#include "raytracer/render/integrators/mis_window.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "raytracer/scene/film_limits.hpp"

namespace sweeptrace {

VcmIntegrator::VcmIntegrator(const Scene& scene, const Accel& accel, const CameraModel& camera,
                             const BdptIntegrator& bdpt, int max_depth)
    : scene_(scene), bdpt_(bdpt), max_depth_(max_depth), r1_(first_radius(scene, accel, camera)) {
    for (const Object& o : scene.objects) merging_ = merging_ && !(scene.camera.shutter && o.motion.moving());
    pixels_ = static_cast<std::size_t>(scene.film.width) * static_cast<std::size_t>(scene.film.height);
    runs_.resize(pixels_);
    // The radii the schedule may take. Below the rounding of the scene's largest coordinate no
    // two points can be told apart (and a grid cell index, |p| / 2r, stays below 2^22); above the
    // scene's size every photon is in range already. Both also keep eta = pi r^2 N a normal,
    // finite float for this N.
    const collision::Bounds3 world = scene_world_bounds(scene);
    float extent = world.empty() ? 1.0f : std::max({glm::length(world.lo), glm::length(world.hi), glm::length(world.hi - world.lo)});
    if (!std::isfinite(extent) || !(extent > 0.0f)) extent = 1.0f;
    const double n = static_cast<double>(pixels_);
    const double eta_lo = std::sqrt(double(std::numeric_limits<float>::min()) / (kPi * n));
    const double eta_hi = std::sqrt(double(std::numeric_limits<float>::max()) / (kPi * n));
    r_min_ = static_cast<float>(std::max(double(extent) * std::numeric_limits<float>::epsilon(), 2.0 * eta_lo));
    r_max_ = static_cast<float>(std::max(double(r_min_), std::min(double(extent), 0.5 * eta_hi)));
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
    if (scene.film.vcm_radius > 0.0f) return scene.film.vcm_radius;  // the loader kept it in vcm_radius_range
    // The default too stays in the range whose schedule keeps pi r^2 N and the grid's cells finite
    // and non-zero (scene/film_limits.hpp): a scene at +-1e18 has pixel footprints beyond it.
    const RadiusRange range = vcm_radius_range();
    const float footprint = median_pixel_footprint(scene, accel, camera);
    if (footprint > 0.0f) return std::clamp(kDefaultPixelFootprints * footprint, range.lo, range.hi);
    // Nothing seen: photons never meet a camera vertex that matters; any finite radius will do.
    const collision::Bounds3 world = scene_world_bounds(scene);
    const float r = world.empty() ? 1.0f : 0.5f * glm::length(world.hi - world.lo);
    return std::clamp(0.003f * (std::isfinite(r) && r > 0.0f ? r : 1.0f), range.lo, range.hi);
}

float VcmIntegrator::radius(int iteration) const {
    const double r = double(r1_) * std::pow(double(iteration) + 1.0, 0.5 * (double(kAlpha) - 1.0));
    return static_cast<float>(std::clamp(r, double(r_min_), double(r_max_)));
}

float VcmIntegrator::merge_density(int iteration) const {
    const double r = radius(iteration);
    return static_cast<float>(kPi * r * r * static_cast<double>(pixels_));
}

void VcmIntegrator::begin_iteration(int iteration, int tiles) {
    radius_ = radius(iteration);
    eta_ = merging_ ? merge_density(iteration) : 0.0f;
    light_.resize(static_cast<std::size_t>(tiles));
    // A pixel the light pass skips (a cancelled pass, which is dropped) has no light vertices.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels_, 1 << 16), [&](const tbb::blocked_range<std::size_t>& r) {
        std::fill(runs_.begin() + static_cast<std::ptrdiff_t>(r.begin()), runs_.begin() + static_cast<std::ptrdiff_t>(r.end()),
                  PixelRun{});
    });
}

// A tile's light vertices go to a scratch store of the thread's first (its capacity kept), then
// to the tile's at their exact size: the iteration's stores hold no growth slack.
namespace {
LightVertices& scratch_store() {
    thread_local LightVertices scratch;
    return scratch;
}
}  // namespace

void VcmIntegrator::trace_light(int tile, std::size_t pixel, float time, PixelSampler& sampler, std::uint64_t& rays,
                                std::vector<Splat>& splats) {
    LightVertices& scratch = scratch_store();
    const auto first = static_cast<std::uint32_t>(scratch.size());
    bdpt_.light_subpath(time, sampler, rays, eta_, scratch, splats);
    runs_[pixel] = {static_cast<std::uint32_t>(tile), first, static_cast<std::uint32_t>(scratch.size()) - first};
}

void VcmIntegrator::finish_tile(int tile) {
    LightVertices& scratch = scratch_store();
    LightVertices& store = light_[static_cast<std::size_t>(tile)];
    store.clear();
    store.append(scratch);
    scratch.clear();
}

void VcmIntegrator::build_grid() {
    std::vector<std::span<const Photon>> runs;
    if (eta_ > 0.0f) {
        runs.reserve(light_.size());
        for (const LightVertices& tile : light_) runs.push_back(tile.photons());
    }
    grid_.build(runs, 2.0f * radius_);
}

glm::vec3 VcmIntegrator::sample(std::size_t pixel, float x, float y, const glm::vec2& lens, float time,
                                PixelSampler& sampler, std::uint64_t& rays, SampleFeatures* features) const {
    thread_local std::vector<PathVertex> cam;
    const PixelRun& run = runs_[pixel];
    glm::vec3 l = bdpt_.camera_subpath(x, y, lens, time, sampler, rays, light_[run.tile], run.first, run.count, eta_,
                                       cam, features);
    if (!(eta_ > 0.0f)) return l;
    for (int j = 1; j < static_cast<int>(cam.size()) && j < max_depth_ && !bdpt_.cancelled(); ++j) {  // cut: pass dropped
        const MaterialParameters& mat = cam[static_cast<std::size_t>(j)].mat(scene_);
        if (scatters(mat) && !is_delta(mat)) l += merge(cam, j);
    }
    return l;
}

// Merging at cam[j] = x_s with every photon (light[s] of some pixel's subpath) within the radius
// whose surface faces the same way: the photon's power times the camera's f |wi.ns| over the
// photon's own |wi.ng| (its power is per unit of its surface's geometric area), by the kernel
// 1 / (pi r^2) and 1 / N for the N light subpaths, so 1 / eta.
glm::vec3 VcmIntegrator::merge(const std::vector<PathVertex>& cam, int j) const {
    const PathVertex& z = cam[static_cast<std::size_t>(j)];
    const MaterialParameters& mat = z.mat(scene_);
    const float r2 = radius_ * radius_;
    MisPath m;
    glm::vec3 sum(0.0f);
    grid_.for_each_near(z.point(), radius_, [&](const Photon& y) {
        const glm::vec3 d = y.point - z.point();
        if (glm::dot(d, d) > r2) return;
        const int s = y.mis.depth, k = s + j;
        if (k > max_depth_) return;
        // Only a photon on a surface facing this one's way: light arriving at a wall is
        // no sample of what arrives at the floor beside it (a leak around the corner).
        if (!(glm::dot(y.normal, z.hit.normal) > 0.0f)) return;
        const BsdfEvalBoth e = eval_bsdf_both(mat, z.hit, z.wo, y.wo);
        // The photon's power is per unit of its own surface's area: its own geometric
        // cosine turns it back into radiance, the camera BSDF's shading cosine applies it.
        const float cos_g = std::abs(glm::dot(y.wo, y.normal));
        if (!(e.pdf_wi > 0.0f) || !(cos_g > 0.0f)) return;
        const glm::vec3 c = z.beta * e.f_cos * y.beta / cos_g;
        if (!(max_component(c) > 0.0f)) return;
        // The path x_0..x_s of the photon's subpath + cam[j..0], x_s the camera's vertex: the
        // camera BSDF's densities toward the photon's predecessor (through the photon's own
        // last segment, SmallVCM's) and toward cam[j - 1].
        m.reset(k, s - 1, std::min(k, s + 2));
        put_light_end(m, y.mis, e.pdf_wi);
        const float fl_next = j >= 2 ? area_density(e.pdf_wo, z.point(), cam[static_cast<std::size_t>(j - 1)]) : 0.0f;
        put_camera_end(m, cam, j, s, y.mis.pdf_own, fl_next);
        sum += c * mis_weight(m, s, true, eta_);
    });
    return sum / eta_;
}

}  // namespace sweeptrace

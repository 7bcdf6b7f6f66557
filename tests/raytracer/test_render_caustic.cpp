// scenes/caustic.json (a small light over rippled water over a diffuse floor, seen from below the
// water's level): the floor under the water is lit only through two refractions, which light
// paths find every time and camera paths only by hitting the small light. The scene names vcm
// (its golden is vcm's); bdpt's connections find this view's caustic as well. At four times their
// samples (1.4x bdpt's CPU time: 1.01 s against 0.70 s at ten times these counts, by hand; vcm
// costs more per sample than bdpt) the path tracer's picture of that region is black with a few
// fireflies: its median pixel and its displayed (clamped) mean are a small fraction of theirs,
// while its plain mean is not small, being unbiased and made of those few fireflies. On the floor
// lit directly they agree: the scene is what the bidirectional methods are for, not a scene the
// path tracer gets wrong everywhere.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "raytracer/accel/accel.hpp"
#include "raytracer/render/camera.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"

using namespace sweeptrace;

namespace {

constexpr float kSlabInset = 0.9f;  // tools/make_caustic_water.py's slab spans |x|, |z| <= 1

// Which floor region a pixel's centre ray meets: 1 under the water slab (inset), 2 the floor lit
// directly (clear of the slab's shadow cone from the light at height 2.2: |x| or |z| > 1.7),
// 0 anything else. The camera is below the water, so a downward ray meets the floor first.
int region_of(const CameraModel& camera, int x, int y) {
    const collision::Ray ray = camera.generate(x + 0.5f, y + 0.5f, 0.5f, 0.5f);
    if (ray.dir.y >= 0.0f) return 0;
    const float t = -ray.origin.y / ray.dir.y;
    const float px = ray.origin.x + t * ray.dir.x, pz = ray.origin.z + t * ray.dir.z;
    if (std::abs(px) < kSlabInset && std::abs(pz) < kSlabInset) return 1;
    if ((std::abs(px) > 1.7f || std::abs(pz) > 1.7f) && pz < 2.5f) return 2;
    return 0;
}

struct RegionMeans {
    double caustic = 0.0, direct = 0.0;  // channel means over the region's pixels
    double caustic_median = 0.0;         // the caustic region's median pixel (channel mean)
    double caustic_shown = 0.0;          // its mean as displayed: each channel clamped to [0, 1]
};

RegionMeans region_means(const Scene& scene, const Image& image) {
    const CameraModel camera(scene.camera, image.width, image.height, scene.film.filter);
    double sum[3] = {0, 0, 0};
    int count[3] = {0, 0, 0};
    std::vector<double> caustic;
    double shown = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const int r = region_of(camera, x, y);
            const glm::vec3 c = image.at(x, y);
            sum[r] += (c.x + c.y + c.z) / 3.0;
            ++count[r];
            if (r != 1) continue;
            caustic.push_back((c.x + c.y + c.z) / 3.0);
            shown += (std::min(c.x, 1.0f) + std::min(c.y, 1.0f) + std::min(c.z, 1.0f)) / 3.0;
        }
    REQUIRE(count[1] > 50);  // the regions are where the scene puts them
    REQUIRE(count[2] > 50);
    std::nth_element(caustic.begin(), caustic.begin() + caustic.size() / 2, caustic.end());
    return {sum[1] / count[1], sum[2] / count[2], caustic[caustic.size() / 2], shown / count[1]};
}

RenderResult render_caustic(const Scene& scene, const Accel& accel, IntegratorKind integrator, int spp) {
    RenderOptions o;
    o.integrator = integrator;
    o.spp = spp;
    o.max_depth = scene.film.max_depth;
    o.seed = 5;
    return render(scene, accel, o);
}

}  // namespace

TEST_CASE("caustic scene: the path tracer leaves the caustic dark where bdpt and vcm find it", "[render][bdpt][vcm][caustic]") {
    Scene scene = load_scene(std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes" / "caustic.json");
    scene.film.width = 48;
    scene.film.height = 30;
    scene.film.clamp_indirect = 0.0f;  // both estimate the unclamped image
    REQUIRE(scene.film.integrator == IntegratorKind::Vcm);  // the scene names the method it is for
    const auto accel = make_accel(AccelKind::Bvh, scene);

    const RegionMeans path = region_means(scene, render_caustic(scene, *accel, IntegratorKind::Path, 64).image);
    for (const IntegratorKind method : {IntegratorKind::Bdpt, IntegratorKind::Vcm}) {
        const RegionMeans found = region_means(scene, render_caustic(scene, *accel, method, 16).image);
        WARN((method == IntegratorKind::Vcm ? "vcm" : "bdpt")
             << " against path: caustic region mean " << found.caustic << " / " << path.caustic << "; median "
             << found.caustic_median << " / " << path.caustic_median << "; displayed mean " << found.caustic_shown
             << " / " << path.caustic_shown << "; directly lit floor: mean " << found.direct << " / " << path.direct);
        // The path tracer's mean there is not small (it is unbiased; a handful of pixels hit the
        // light and carry its whole radiance): its picture is. Its typical pixel and what a display shows.
        CHECK(path.caustic_median < 0.1 * found.caustic_median);
        CHECK(path.caustic_shown < 0.2 * found.caustic_shown);
        CHECK(std::abs(path.direct / found.direct - 1.0) < 0.1);
    }
}

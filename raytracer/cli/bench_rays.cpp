#include "raytracer/cli/bench_rays.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <random>

#include <glm/geometric.hpp>

#include "raytracer/render/camera.hpp"

namespace sweeptrace {

double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<collision::Ray> make_bench_rays(const Scene& scene, const Accel& accel, int primaries, std::uint64_t seed) {
    const CameraModel camera(scene.camera, scene.film.width, scene.film.height);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    std::vector<collision::Ray> rays;
    rays.reserve(2 * static_cast<std::size_t>(primaries));
    for (int i = 0; i < primaries; ++i) {
        const collision::Ray primary = camera.generate(u(rng) * static_cast<float>(scene.film.width),
                                                      u(rng) * static_cast<float>(scene.film.height), u(rng), u(rng));
        rays.push_back(primary);
        SurfaceHit hit;
        if (!accel.intersect(primary, hit)) continue;
        glm::vec3 d(gauss(rng), gauss(rng), gauss(rng));
        if (glm::dot(d, d) == 0.0f) d = hit.normal;
        if (glm::dot(d, hit.normal) < 0.0f) d = -d;
        rays.push_back(spawn_ray(hit, glm::normalize(d)));
    }
    return rays;
}

template <class Query>
TraceResult time_pass(const std::vector<collision::Ray>& rays, Query&& query) {
    TraceResult r;
    const double c0 = thread_cpu_seconds(), w0 = wall_seconds();
    for (const collision::Ray& ray : rays) r.hits += query(ray);
    r.cpu = thread_cpu_seconds() - c0;
    r.wall = wall_seconds() - w0;
    return r;
}

TraceResult time_intersect(const Accel& accel, const std::vector<collision::Ray>& rays) {
    return time_pass(rays, [&](const collision::Ray& ray) {
        SurfaceHit hit;
        return accel.intersect(ray, hit);
    });
}

TraceResult time_occluded(const Accel& accel, const std::vector<collision::Ray>& rays) {
    return time_pass(rays, [&](const collision::Ray& ray) { return accel.occluded(ray); });
}

void warm_up(const Accel& accel, const std::vector<collision::Ray>& rays) {
    const std::vector<collision::Ray> slice(rays.begin(), rays.begin() + std::min<std::size_t>(rays.size(), 10000));
    time_intersect(accel, slice);
    time_occluded(accel, slice);
}

}  // namespace sweeptrace

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

namespace {

// The key light of make_bench_rays: a square, centre and two half-side vectors.
struct KeyLight {
    glm::vec3 centre, half_u, half_v, normal;

    explicit KeyLight(const Camera& camera) {
        const glm::vec3 back = camera.position - camera.look_at;
        const float distance = glm::length(back);
        const glm::vec3 w = back / distance;
        const glm::vec3 right = glm::normalize(glm::cross(camera.up, w));
        const glm::vec3 up = glm::cross(w, right);
        centre = camera.look_at + distance * glm::normalize(w + 0.8f * up + 0.6f * right);
        normal = glm::normalize(camera.look_at - centre);
        const glm::vec3 u = glm::normalize(glm::cross(normal, up));
        half_u = 0.1f * distance * u;
        half_v = 0.1f * distance * glm::cross(normal, u);
    }

    glm::vec3 point(float u1, float u2) const { return centre + (2.0f * u1 - 1.0f) * half_u + (2.0f * u2 - 1.0f) * half_v; }
};

}  // namespace

BenchRays make_bench_rays(const Scene& scene, const Accel& accel, int primaries, std::uint64_t seed) {
    const CameraModel camera(scene.camera, scene.film.width, scene.film.height);
    const KeyLight light(scene.camera);
    std::mt19937_64 rng(seed);
    std::mt19937_64 bounce_rng(seed ^ 0x9e3779b97f4a7c15ull);  // the bounce vertices' light samples
    // Times from their own stream, so a still scene's rays are the ones they were.
    std::mt19937_64 time_rng(seed ^ 0x7f4a7c159e3779b9ull);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    const bool timed = scene.camera.shutter;
    BenchRays out;
    out.rays.reserve(2 * static_cast<std::size_t>(primaries));
    out.shadow.reserve(static_cast<std::size_t>(primaries));
    for (int i = 0; i < primaries; ++i) {
        const collision::Ray primary = camera.generate(u(rng) * static_cast<float>(scene.film.width),
                                                      u(rng) * static_cast<float>(scene.film.height), u(rng), u(rng));
        out.rays.push_back(primary);
        const float time = timed ? u(time_rng) : 0.0f;
        if (timed) out.ray_times.push_back(time);
        SurfaceHit hit;
        if (!(timed ? accel.intersect(primary, time, hit) : accel.intersect(primary, hit))) continue;
        glm::vec3 d(gauss(rng), gauss(rng), gauss(rng));
        if (glm::dot(d, d) == 0.0f) d = hit.normal;
        if (glm::dot(d, hit.normal) < 0.0f) d = -d;
        out.rays.push_back(spawn_ray(hit, glm::normalize(d)));
        const float u1 = u(rng), u2 = u(rng);
        out.shadow.push_back(spawn_ray_to(hit, light.point(u1, u2), glm::vec3(0.0f), light.normal));
        if (timed) {
            out.ray_times.push_back(time);
            out.shadow_times.push_back(time);
        }
        SurfaceHit bounce_hit;
        if (!(timed ? accel.intersect(out.rays.back(), time, bounce_hit) : accel.intersect(out.rays.back(), bounce_hit)))
            continue;
        const float u3 = u(bounce_rng), u4 = u(bounce_rng);
        out.shadow_bounce.push_back(spawn_ray_to(bounce_hit, light.point(u3, u4), glm::vec3(0.0f), light.normal));
        if (timed) out.shadow_bounce_times.push_back(time);
    }
    return out;
}

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
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

// The same with each ray's time (the queries at a shutter fraction).
template <class Query>
TraceResult time_pass_timed(const std::vector<collision::Ray>& rays, const std::vector<float>& times, Query&& query) {
    TraceResult r;
    const double c0 = thread_cpu_seconds(), w0 = wall_seconds();
    for (std::size_t i = 0; i < rays.size(); ++i) r.hits += query(rays[i], times[i]);
    r.cpu = thread_cpu_seconds() - c0;
    r.wall = wall_seconds() - w0;
    return r;
}

TraceResult median_of(const std::vector<TraceResult>& passes) {
    std::vector<double> cpu, wall;
    for (const TraceResult& p : passes) {
        cpu.push_back(p.cpu);
        wall.push_back(p.wall);
    }
    return TraceResult{median(cpu), median(wall), passes.front().hits};  // hits: the same every pass
}

template <class Query>
PairTimes time_alternating(const std::vector<collision::Ray>& rays, int repeats, Query&& native, Query&& embree) {
    std::vector<TraceResult> a, b;
    for (int k = 0; k < std::max(1, repeats); ++k) {
        a.push_back(time_pass(rays, native));
        b.push_back(time_pass(rays, embree));
    }
    return PairTimes{median_of(a), median_of(b)};
}

template <class Query>
PairTimes time_alternating_timed(const std::vector<collision::Ray>& rays, const std::vector<float>& times, int repeats,
                                 Query&& native, Query&& embree) {
    std::vector<TraceResult> a, b;
    for (int k = 0; k < std::max(1, repeats); ++k) {
        a.push_back(time_pass_timed(rays, times, native));
        b.push_back(time_pass_timed(rays, times, embree));
    }
    return PairTimes{median_of(a), median_of(b)};
}

auto intersect_at_query(const Accel& accel) {
    return [&accel](const collision::Ray& ray, float time) {
        SurfaceHit hit;
        return accel.intersect(ray, time, hit);
    };
}

auto occluded_at_query(const Accel& accel) {
    return [&accel](const collision::Ray& ray, float time) { return accel.occluded(ray, time); };
}

auto intersect_query(const Accel& accel) {
    return [&accel](const collision::Ray& ray) {
        SurfaceHit hit;
        return accel.intersect(ray, hit);
    };
}

auto occluded_query(const Accel& accel) {
    return [&accel](const collision::Ray& ray) { return accel.occluded(ray); };
}

}  // namespace

PairTimes time_intersect(const Accel& native, const Accel& embree, const std::vector<collision::Ray>& rays, int repeats,
                         const std::vector<float>& times) {
    if (!times.empty())
        return time_alternating_timed(rays, times, repeats, intersect_at_query(native), intersect_at_query(embree));
    return time_alternating(rays, repeats, intersect_query(native), intersect_query(embree));
}

PairTimes time_occluded(const Accel& native, const Accel& embree, const std::vector<collision::Ray>& rays, int repeats,
                        const std::vector<float>& times) {
    if (!times.empty())
        return time_alternating_timed(rays, times, repeats, occluded_at_query(native), occluded_at_query(embree));
    return time_alternating(rays, repeats, occluded_query(native), occluded_query(embree));
}

ShadowTimes time_shadow(const Accel& native, const Accel& embree, const std::vector<collision::Ray>& rays, int repeats,
                        const std::vector<float>& times) {
    const PairTimes occluded = time_occluded(native, embree, rays, repeats, times);
    const PairTimes intersect = time_intersect(native, embree, rays, repeats, times);
    return ShadowTimes{occluded.native, occluded.embree, intersect.native, intersect.embree};
}

SplitRays split_blocked(const Accel& accel, const std::vector<collision::Ray>& rays) {
    SplitRays out;
    for (const collision::Ray& ray : rays) (accel.occluded(ray) ? out.blocked : out.unblocked).push_back(ray);
    return out;
}

void warm_up(const Accel& accel, const BenchRays& bench) {
    for (const std::vector<collision::Ray>* rays : {&bench.rays, &bench.shadow}) {
        const std::vector<collision::Ray> slice(rays->begin(), rays->begin() + std::min<std::size_t>(rays->size(), 10000));
        time_pass(slice, intersect_query(accel));
        time_pass(slice, occluded_query(accel));
    }
    if (bench.ray_times.empty()) return;
    for (const auto& [rays, times] : {std::pair{&bench.rays, &bench.ray_times}, std::pair{&bench.shadow, &bench.shadow_times}}) {
        const std::size_t n = std::min<std::size_t>(rays->size(), 10000);
        const std::vector<collision::Ray> slice(rays->begin(), rays->begin() + n);
        const std::vector<float> at(times->begin(), times->begin() + n);
        time_pass_timed(slice, at, intersect_at_query(accel));
        time_pass_timed(slice, at, occluded_at_query(accel));
    }
}

}  // namespace sweeptrace

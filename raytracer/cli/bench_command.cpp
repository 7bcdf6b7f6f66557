// `sweeptrace bench SCENE [--rays N] [--repeat N] [--threads N] [--spp N]`: the native BVH
// against Embree on the same scene and the same rays, single-threaded, each timing the median of
// --repeat passes: build time, Mrays/s (primary rays through the camera plus one random bounce
// from each primary hit; occluded() on shadow rays from each primary hit, and from each bounce
// hit, to a key light), their ratio, bytes per triangle; then samples/s of a short render at 1
// and up to --threads threads. It prints figures; it asserts nothing. `sweeptrace bench --meshes
// DIR` does the same per OBJ file of DIR (bench_meshes.hpp). Ray rates are per second of the
// tracing thread's CPU time (bench_rays.hpp). A scene with a camera shutter is timed with each ray at
// a random time in it (the queries of moving objects).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/accel/embree_accel.hpp"
#include "raytracer/cli/bench_meshes.hpp"
#include "raytracer/cli/bench_rays.hpp"
#include "raytracer/cli/commands.hpp"
#include "raytracer/cli/memory_budget.hpp"
#include "raytracer/cli/render_limits.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/film_limits.hpp"
#include "raytracer/scene/load_scene.hpp"

namespace sweeptrace {
namespace {

struct BenchArgs {
    std::string scene;
    std::string meshes;
    int rays = 200000;
    int threads = 2;
    int spp = 2;
    int repeat = 5;
};

void run_bench(const BenchArgs& args) {
    if (args.rays < 1) throw InputError("bench: --rays must be >= 1, got " + std::to_string(args.rays));
    if (args.repeat < 1 || args.repeat > 1000)
        throw InputError("bench: --repeat must be in [1, 1000], got " + std::to_string(args.repeat));
    if (args.threads < 1 || args.threads > kMaxThreads)
        throw InputError("bench: --threads must be in [1, " + std::to_string(kMaxThreads) + "], got " + std::to_string(args.threads));
    if (const std::string problem = film_setting_problem(FilmSetting::Spp, args.spp); !problem.empty())
        throw InputError("bench: --spp " + problem);
    if (args.scene.empty() == args.meshes.empty())
        throw InputError("bench: give either a scene file or --meshes DIR, not both or neither");
    if (!args.meshes.empty()) {
        run_mesh_bench(args.meshes, args.rays, args.repeat);
        return;
    }
    const Scene scene = load_scene(args.scene);
    check_render_memory(scene, std::nullopt);

    double w0 = wall_seconds();
    const BvhAccel native(scene);
    const double native_build = wall_seconds() - w0;
    EmbreeOptions single_thread;
    single_thread.build_threads = 1;
    w0 = wall_seconds();
    std::unique_ptr<Accel> embree = make_embree_accel(scene, single_thread);
    const double embree_build = wall_seconds() - w0;

    const std::size_t triangles = native.triangle_count();
    std::printf("scene %s: %zu objects, %zu triangles in %zu meshes\n", args.scene.c_str(), scene.objects.size(),
                triangles, scene.meshes.size());
    std::printf("%-8s %10s %12s %14s\n", "accel", "build s", "memory B", "B/triangle");
    for (const auto& [accel, build] : {std::pair<const Accel*, double>{&native, native_build}, {embree.get(), embree_build}}) {
        const double per_tri = triangles ? static_cast<double>(accel->memory_bytes()) / static_cast<double>(triangles) : 0.0;
        std::printf("%-8s %10.3f %12zu %14.1f\n", accel->name().c_str(), build, accel->memory_bytes(), per_tri);
    }

    if (native.time_slices() > 0)
        std::printf("bvh: moving objects, the shutter cut into %zu time slice%s (accel/time_slices.hpp)\n",
                    native.time_slices(), native.time_slices() == 1 ? "" : "s");
    const BenchRays bench = make_bench_rays(scene, native, args.rays, scene.seed);
    const std::vector<collision::Ray>& rays = bench.rays;
    warm_up(native, bench);
    warm_up(*embree, bench);
    const PairTimes isect = time_intersect(native, *embree, rays, args.repeat, bench.ray_times);
    const TraceResult &a = isect.native, &b = isect.embree;
    const double mrays = 1e-6 * static_cast<double>(rays.size());
    std::printf("%zu rays (%d primary + %zu bounce), single-threaded, median of %d pass%s%s:\n", rays.size(), args.rays,
                rays.size() - static_cast<std::size_t>(args.rays), args.repeat, args.repeat == 1 ? "" : "es",
                bench.ray_times.empty() ? "" : ", each at a random time in the shutter (motion blur)");
    std::printf("%-8s %14s %15s %10s\n", "accel", "Mrays/s (cpu)", "Mrays/s (wall)", "hits");
    std::printf("%-8s %14.3f %15.3f %10zu\n", native.name().c_str(), mrays / a.cpu, mrays / a.wall, a.hits);
    std::printf("%-8s %14.3f %15.3f %10zu\n", embree->name().c_str(), mrays / b.cpu, mrays / b.wall, b.hits);
    std::printf("native / embree: %.2fx (cpu time), %.2fx (wall time)\n", b.cpu / a.cpu, b.wall / a.wall);
    // Shadow rays (a segment from each primary hit to a key light): occluded(), and intersect()
    // on the same segments for the any-hit traversal's gain.
    const ShadowTimes shadow = time_shadow(native, *embree, bench.shadow, args.repeat, bench.shadow_times);
    const TraceResult &ao = shadow.native_occluded, &bo = shadow.embree_occluded;
    const TraceResult &as = shadow.native_intersect, &bs = shadow.embree_intersect;
    const double mshadow = 1e-6 * static_cast<double>(bench.shadow.size());
    std::printf("%zu shadow rays (one per primary hit, to a key light), %zu / %zu occluded:\n", bench.shadow.size(),
                ao.hits, bo.hits);
    std::printf("occluded: %s %.3f, %s %.3f Mrays/s (cpu); native / embree %.2fx; occluded / intersect: native %.2fx, "
                "embree %.2fx\n",
                native.name().c_str(), mshadow / ao.cpu, embree->name().c_str(), mshadow / bo.cpu, bo.cpu / ao.cpu,
                as.cpu / ao.cpu, bs.cpu / bo.cpu);
    // The shadow rays a render also traces: from each bounce hit to the key light.
    const ShadowTimes second = time_shadow(native, *embree, bench.shadow_bounce, args.repeat, bench.shadow_bounce_times);
    const double mbounce = 1e-6 * static_cast<double>(bench.shadow_bounce.size());
    if (!bench.shadow_bounce.empty())
        std::printf("%zu shadow rays from the bounce hits, %zu / %zu occluded:\noccluded: %s %.3f, %s %.3f Mrays/s (cpu); "
                    "native / embree %.2fx; occluded / intersect: native %.2fx, embree %.2fx\n",
                    bench.shadow_bounce.size(), second.native_occluded.hits, second.embree_occluded.hits,
                    native.name().c_str(), mbounce / second.native_occluded.cpu, embree->name().c_str(),
                    mbounce / second.embree_occluded.cpu, second.embree_occluded.cpu / second.native_occluded.cpu,
                    second.native_intersect.cpu / second.native_occluded.cpu,
                    second.embree_intersect.cpu / second.embree_occluded.cpu);
    // An Embree device made with "threads=1" caps TBB's parallelism for the whole process while
    // it lives, which would make the multi-threaded render below run on one core.
    embree.reset();

    for (int threads : {1, args.threads}) {
        RenderOptions options;
        options.spp = args.spp;
        options.max_depth = scene.film.max_depth;
        options.threads = threads;
        options.seed = scene.seed;
        const RenderResult result = render(scene, native, options);
        std::printf("render %dx%d, %d spp, %d thread%s: %.2f s, %.0f samples/s, %.2f Mrays/s\n", scene.film.width,
                    scene.film.height, args.spp, threads, threads == 1 ? "" : "s", result.stats.seconds,
                    static_cast<double>(result.stats.samples) / result.stats.seconds,
                    1e-6 * static_cast<double>(result.stats.rays) / result.stats.seconds);
        if (threads == args.threads) break;
    }
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<BenchArgs>();
    auto* cmd = app.add_subcommand("bench", "Time the native BVH against Embree on a scene or a folder of meshes (prints figures)");
    cmd->add_option("scene", args->scene, "Scene file (JSON)");
    cmd->add_option("--meshes", args->meshes, "Instead of a scene: every .obj file of this folder, framed alone");
    cmd->add_option("--rays", args->rays, "Primary rays (each hit adds one bounce ray)")->capture_default_str();
    cmd->add_option("--repeat", args->repeat, "Passes over the same rays per timing (the median is printed)")
        ->capture_default_str();
    cmd->add_option("--threads", args->threads, "Most threads for the render timing")->capture_default_str();
    cmd->add_option("--spp", args->spp, "Samples per pixel of the render timing")->capture_default_str();
    cmd->callback([args, &exit_code] {
        run_bench(*args);
        exit_code = 0;
    });
}

}  // namespace sweeptrace

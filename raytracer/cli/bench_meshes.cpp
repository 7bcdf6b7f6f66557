#include "raytracer/cli/bench_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/accel/embree_accel.hpp"
#include "raytracer/accel/embree_sah.hpp"
#include "raytracer/cli/bench_rays.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/obj_loader.hpp"

namespace sweeptrace {
namespace {

std::vector<std::filesystem::path> obj_files(const std::string& dir) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) throw InputError("bench: --meshes " + dir + ": not a folder");
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.is_regular_file() && entry.path().extension() == ".obj") files.push_back(entry.path());
    if (ec) throw InputError("bench: --meshes " + dir + ": " + ec.message());
    if (files.empty()) throw InputError("bench: --meshes " + dir + ": no .obj file in it");
    std::sort(files.begin(), files.end());
    return files;
}

// The mesh alone, seen from the front and a little above so its bounding sphere fills the
// film's height, identity transform (one mesh instance), seed fixed.
Scene framed_scene(Mesh mesh) {
    Scene scene;
    collision::Bounds3 box;
    for (const glm::vec3& v : mesh.triangles.vertices) box.extend(v);
    const glm::vec3 centre = 0.5f * (box.lo + box.hi);
    const float radius = 0.5f * glm::length(box.hi - box.lo);
    scene.camera.vfov_degrees = 40.0f;
    scene.camera.look_at = centre;
    const float distance = radius / std::sin(glm::radians(0.5f * scene.camera.vfov_degrees));
    scene.camera.position = centre + distance * glm::normalize(glm::vec3(0.25f, 0.35f, 1.0f));
    scene.film.width = scene.film.height = 320;
    scene.materials.push_back(Material{});
    scene.meshes.push_back(std::move(mesh));
    Object object;
    object.shape = MeshInstance{0};
    object.name = "mesh";
    scene.objects.push_back(std::move(object));
    scene.seed = 1;
    return scene;
}

void print_shadow_detail(const Accel& native, const Accel& embree, const BenchRays& bench, int repeats);

struct Timed {
    double cpu = 0.0, wall = 0.0;
};

template <class Build>
auto timed_build(Timed& t, Build&& build) {
    const double c0 = thread_cpu_seconds(), w0 = wall_seconds();
    auto result = build();
    t.cpu = thread_cpu_seconds() - c0;
    t.wall = wall_seconds() - w0;
    return result;
}

void bench_one(const std::filesystem::path& file, int primaries, int repeats) {
    const Scene scene = framed_scene(load_obj(file));
    const std::size_t triangles = scene.meshes[0].triangles.triangle_count();
    Timed native_build, embree_build;
    const auto native = timed_build(native_build, [&] { return std::make_unique<BvhAccel>(scene); });
    EmbreeOptions single_thread;
    single_thread.build_threads = 1;
    const auto embree = timed_build(embree_build, [&] { return make_embree_accel(scene, single_thread); });
    const EmbreeSah embree_sah = embree_builder_sah(scene.meshes[0].triangles);

    const BenchRays bench = make_bench_rays(scene, *native, primaries, scene.seed);
    const std::vector<collision::Ray>& rays = bench.rays;
    warm_up(*native, bench);
    warm_up(*embree, bench);
    const PairTimes isect = time_intersect(*native, *embree, rays, repeats);
    const TraceResult &ni = isect.native, &ei = isect.embree;
    // Shadow rays: occluded() against intersect() on the same segments.
    const ShadowTimes shadow = time_shadow(*native, *embree, bench.shadow, repeats);
    const TraceResult &no = shadow.native_occluded, &eo = shadow.embree_occluded;
    const TraceResult &ns = shadow.native_intersect, &es = shadow.embree_intersect;
    const double mrays = 1e-6 * static_cast<double>(rays.size());
    const double mshadow = 1e-6 * static_cast<double>(bench.shadow.size());
    const double tri = static_cast<double>(triangles);
    std::printf("%-18s %7zu %6zu %6zu  build ms %7.1f %7.1f (%.2fx)  SAH %6.1f %6.1f  B/tri %5.1f %5.1f"
                "  intersect %6.2f %6.2f (%.2fx)  occluded %6.2f %6.2f (%.2fx)  occl/isect %.2f %.2f  blocked %4.1f%%\n",
                file.filename().string().c_str(), triangles, rays.size(), bench.shadow.size(), 1e3 * native_build.cpu,
                1e3 * embree_build.cpu, native_build.cpu / embree_build.cpu, native->mesh_sah_cost(0), embree_sah.cost,
                static_cast<double>(native->memory_bytes()) / tri, static_cast<double>(embree->memory_bytes()) / tri,
                mrays / ni.cpu, mrays / ei.cpu, ei.cpu / ni.cpu, mshadow / no.cpu, mshadow / eo.cpu, eo.cpu / no.cpu,
                ns.cpu / no.cpu, es.cpu / eo.cpu, 100.0 * static_cast<double>(no.hits) / static_cast<double>(bench.shadow.size()));
    if (ni.hits != ei.hits || no.hits != eo.hits)
        std::printf("%-18s note: hits differ, intersect %zu / %zu, occluded %zu / %zu (native / embree)\n", "",
                    ni.hits, ei.hits, no.hits, eo.hits);
    print_shadow_detail(*native, *embree, bench, repeats);
}

// occl/isect of native then embree on `rays`, or n/a for too few rays to time.
std::string occl_isect(const ShadowTimes& t, std::size_t rays) {
    if (rays < 100) return "  n/a  n/a";
    char text[32];
    std::snprintf(text, sizeof text, "%5.2f %4.2f", t.native_intersect.cpu / t.native_occluded.cpu,
                  t.embree_intersect.cpu / t.embree_occluded.cpu);
    return text;
}

// (intersect on the unblocked + on the blocked rays) / occluded on the unblocked ones, native then
// embree, or n/a when the unblocked rays are too few to time (as occl_isect).
std::string ceiling(const ShadowTimes& unblocked, const ShadowTimes& blocked, std::size_t unblocked_rays) {
    if (unblocked_rays < 100) return "n/a";
    char text[48];
    std::snprintf(text, sizeof text, "native %.2f, embree %.2f",
                  (unblocked.native_intersect.cpu + blocked.native_intersect.cpu) / unblocked.native_occluded.cpu,
                  (unblocked.embree_intersect.cpu + blocked.embree_intersect.cpu) / unblocked.embree_occluded.cpu);
    return text;
}

// What any-hit can gain depends on how many shadow rays are blocked: on an unblocked ray both
// traversals visit the same boxes, and occluded() saves only the ordering. So the primary-hit
// shadow rays split into unblocked and blocked, and a second set as a render also traces them:
// from the bounce hits (the path's second vertex) to the key light.
void print_shadow_detail(const Accel& native, const Accel& embree, const BenchRays& bench, int repeats) {
    const SplitRays split = split_blocked(native, bench.shadow);
    const ShadowTimes unblocked = time_shadow(native, embree, split.unblocked, repeats);
    const ShadowTimes blocked = time_shadow(native, embree, split.blocked, repeats);
    const ShadowTimes second = time_shadow(native, embree, bench.shadow_bounce, repeats);
    const double n = static_cast<double>(bench.shadow_bounce.size());
    std::printf("%-18s shadow rays from the primary hits, occl/isect native embree: unblocked %6zu %s, blocked %6zu %s\n",
                "", split.unblocked.size(), occl_isect(unblocked, split.unblocked.size()).c_str(), split.blocked.size(),
                occl_isect(blocked, split.blocked.size()).c_str());
    std::printf("%-18s shadow rays from the bounce hits %6zu, blocked %4.1f%%: occluded %6.2f %6.2f (%.2fx)  occl/isect %s\n",
                "", bench.shadow_bounce.size(), n > 0 ? 100.0 * static_cast<double>(second.native_occluded.hits) / n : 0.0,
                1e-6 * n / second.native_occluded.cpu, 1e-6 * n / second.embree_occluded.cpu,
                second.embree_occluded.cpu / second.native_occluded.cpu, occl_isect(second, bench.shadow_bounce.size()).c_str());
    // The most any-hit could gain on the primary-hit set: occluded() made free on every blocked ray,
    // with the unblocked ones at today's cost (they need every box and triangle test intersect()
    // makes there). A target above this ceiling needs fewer tests on unblocked segments, which an
    // exact any-hit query on the same tree cannot skip.
    std::printf("%-18s occl/isect ceiling if blocked rays cost nothing: %s\n", "",
                ceiling(unblocked, blocked, split.unblocked.size()).c_str());
    if (second.native_occluded.hits != second.embree_occluded.hits)
        std::printf("%-18s note: bounce-hit shadow rays occluded differ, %zu / %zu (native / embree)\n", "",
                    second.native_occluded.hits, second.embree_occluded.hits);
}

}  // namespace

void run_mesh_bench(const std::string& dir, int primaries, int repeats) {
    const std::vector<std::filesystem::path> files = obj_files(dir);
    std::printf("each mesh alone, 320x320, %d primary rays + one bounce per hit; single thread, CPU time of the thread,\n"
                "each timing the median of %d pass%s over the same rays\n",
                primaries, repeats, repeats == 1 ? "" : "es");
    std::printf("columns: native then embree; (x) = native / embree speed (build: native / embree time);\n"
                "intersect on the rays, occluded on the shadow rays (one per primary hit, to a key light),\n"
                "occl/isect = occluded against intersect on those same shadow rays, blocked = share of them occluded;\n"
                "then per mesh those shadow rays split by whether they are blocked, and the shadow rays from the bounce hits;\n"
                "SAH = sum over nodes of area / root area (+1 per node visit, +1 per triangle in a leaf);\n"
                "embree's SAH is that of its rtcBuildBVH builder (8 wide, leaves of <= 4), the build time that of rtcCommitScene\n");
    std::printf("%-18s %7s %6s %6s\n", "mesh", "tris", "rays", "shadow");
    for (const auto& file : files) bench_one(file, primaries, repeats);
}

}  // namespace sweeptrace

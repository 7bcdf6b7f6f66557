#include "raytracer/accuracy/routines.hpp"

#include <algorithm>
#include <memory>

#include "collision/intersect.hpp"
#include "collision/thesis/intersect.hpp"
#include "raytracer/accel/embree_reference.hpp"
#include "raytracer/accuracy/thread_timer.hpp"
#include "raytracer/accuracy/user_routines.hpp"

namespace sweeptrace::accuracy {

using collision::Ray;

namespace {

}  // namespace

// Embree on single triangles: one scene per case, built untimed in chunks; only rtcIntersect1
// is timed.
Variant<collision::Triangle> embree_triangle_variant(bool robust) {
    Variant<collision::Triangle> v;
    v.name = robust ? "embree-robust" : "embree";
    v.batch = [robust](const std::vector<collision::Triangle>& shapes, const std::vector<Ray>& rays,
                       std::vector<Result>& out) {
        out.assign(rays.size(), Result{});
        double seconds = 0.0;
        constexpr std::size_t chunk = 256;
        std::vector<std::unique_ptr<EmbreeTriangles>> scenes;
        for (std::size_t first = 0; first < rays.size(); first += chunk) {
            const std::size_t last = std::min(rays.size(), first + chunk);
            scenes.clear();
            for (std::size_t i = first; i < last; ++i) {
                scenes.push_back(std::make_unique<EmbreeTriangles>(std::vector<collision::Triangle>{shapes[i]}, robust));
            }
            std::vector<EmbreeTriangleHit> hits(last - first);
            const double start = thread_seconds();
            for (std::size_t i = first; i < last; ++i) out[i].hit = scenes[i - first]->intersect(rays[i], hits[i - first]);
            seconds += thread_seconds() - start;
            for (std::size_t i = first; i < last; ++i) {
                if (!out[i].hit) continue;
                const EmbreeTriangleHit& h = hits[i - first];
                out[i].h.t = h.t;
                out[i].h.point = rays[i].at(h.t);  // Embree gives no error bound: offset zero
                out[i].h.normal = h.normal;
                out[i].h.uv = h.uv;
            }
        }
        return seconds;
    };
    v.mesh = [robust](const std::vector<collision::Triangle>& faces, const std::vector<Ray>& rays,
                      std::vector<Result>& out) {
        out.assign(rays.size(), Result{});
        const EmbreeTriangles scene(faces, robust);
        const double start = thread_seconds();
        for (std::size_t i = 0; i < rays.size(); ++i) {
            EmbreeTriangleHit h;
            out[i].hit = scene.intersect(rays[i], h);
            out[i].h.t = h.t;
        }
        // Per face so the rate compares with the brute-force loops of the other variants.
        return (thread_seconds() - start) * double(faces.size());
    };
    return v;
}

namespace {

// The variants measured per shape: the robust default of collision/ for every shape, the
// thesis-faithful one of collision/thesis/ where the thesis has the shape, Embree's test beside
// them for triangles.
template <class S>
std::vector<Variant<S>> variants_for() {
    std::vector<Variant<S>> v{variant_of<S>("robust", &collision::intersect)};
    if constexpr (!std::is_same_v<S, collision::Quad>) {  // the thesis has no quad
        v.push_back(variant_of<S>("thesis", &collision::thesis::intersect));
    }
    if constexpr (std::is_same_v<S, collision::Triangle>) {
        v.push_back(embree_triangle_variant(false));
        v.push_back(embree_triangle_variant(true));
    }
    for (const Variant<S>& mine : registered_variants<S>()) v.push_back(mine);  // user_routines.hpp
    return v;
}

template <class S>
void run_if_selected(const std::vector<std::string>& shapes, std::size_t n, std::uint64_t seed,
                     std::vector<Metrics>& rows) {
    if (!shapes.empty() && std::find(shapes.begin(), shapes.end(), shape_name<S>()) == shapes.end()) return;
    const std::vector<Variant<S>> variants = variants_for<S>();
    if (variants.empty()) return;
    const std::vector<Metrics> r = run_shape<S>(variants, n, seed);
    rows.insert(rows.end(), r.begin(), r.end());
}

}  // namespace

const std::vector<std::string>& routine_shape_names() {
    static const std::vector<std::string> names = {
        shape_name<collision::Sphere>(),   shape_name<collision::Aabb>(),    shape_name<collision::Cylinder>(),
        shape_name<collision::Capsule>(),  shape_name<collision::OrientedCapsule>(),
        shape_name<collision::Ellipsoid>(), shape_name<collision::Plane>(),  shape_name<collision::Disk>(),
        shape_name<collision::Quad>(),     shape_name<collision::Triangle>()};
    return names;
}

std::vector<Metrics> run_routines(const std::vector<std::string>& shapes, std::size_t n, std::uint64_t seed) {
    std::vector<Metrics> rows;
    run_if_selected<collision::Sphere>(shapes, n, seed, rows);
    run_if_selected<collision::Aabb>(shapes, n, seed, rows);
    run_if_selected<collision::Cylinder>(shapes, n, seed, rows);
    run_if_selected<collision::Capsule>(shapes, n, seed, rows);
    run_if_selected<collision::OrientedCapsule>(shapes, n, seed, rows);
    run_if_selected<collision::Ellipsoid>(shapes, n, seed, rows);
    run_if_selected<collision::Plane>(shapes, n, seed, rows);
    run_if_selected<collision::Disk>(shapes, n, seed, rows);
    run_if_selected<collision::Quad>(shapes, n, seed, rows);
    run_if_selected<collision::Triangle>(shapes, n, seed, rows);
    return rows;
}

}  // namespace sweeptrace::accuracy

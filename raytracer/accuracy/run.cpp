#include "raytracer/accuracy/run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "raytracer/accuracy/reference.hpp"
#include "raytracer/accuracy/thread_timer.hpp"

namespace sweeptrace::accuracy {

using collision::Ray;

namespace {

void summarise_t_errors(std::vector<double>& errors, Metrics& m) {
    m.t_scored = errors.size();
    if (errors.empty()) return;
    std::sort(errors.begin(), errors.end());
    const auto at = [&](double q) { return errors[std::min(errors.size() - 1, std::size_t(q * double(errors.size())))]; };
    m.t_median = at(0.5);
    m.t_p99 = at(0.99);
    m.t_max = errors.back();
}

double relative(long double t, long double t_ref) {
    return static_cast<double>(std::fabs(t - t_ref) / std::max(std::fabs(t_ref), std::numeric_limits<long double>::min()));
}

}  // namespace

template <class S>
Variant<S> variant_of(std::string name, bool (*fn)(const Ray&, const S&, collision::RayHit&)) {
    Variant<S> v;
    v.name = std::move(name);
    v.batch = [fn](const std::vector<S>& shapes, const std::vector<Ray>& rays, std::vector<Result>& out) {
        // Best of three runs: the machine is shared, the minimum is the least disturbed figure.
        double best = std::numeric_limits<double>::infinity();
        for (int run = 0; run < 3; ++run) {
            out.assign(rays.size(), Result{});
            const double start = thread_seconds();
            for (std::size_t i = 0; i < rays.size(); ++i) out[i].hit = fn(rays[i], shapes[i], out[i].h);
            best = std::min(best, thread_seconds() - start);
        }
        return best;
    };
    v.mesh = [fn](const std::vector<S>& faces, const std::vector<Ray>& rays, std::vector<Result>& out) {
        out.assign(rays.size(), Result{});
        const double start = thread_seconds();
        for (std::size_t i = 0; i < rays.size(); ++i) {
            Ray r = rays[i];
            for (const S& f : faces) {
                if (fn(r, f, out[i].h)) {
                    out[i].hit = true;
                    r.tmax = out[i].h.t;  // nearest: only closer hits from here on
                }
            }
        }
        return thread_seconds() - start;
    };
    return v;
}

template <class S>
Metrics score(const std::vector<S>& shapes, const std::vector<Ray>& rays, const std::vector<Result>& results) {
    Metrics m;
    m.rays = rays.size();
    std::vector<double> errors;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const RefHit ref = reference(rays[i], shapes[i]);
        if (ref.outcome == RefOutcome::Boundary) {
            ++m.boundary;
            continue;
        }
        const bool ref_hit = ref.outcome == RefOutcome::Hit;
        const bool clear = reference(rays[i], shapes[i], float_band).outcome != RefOutcome::Boundary;
        if (!clear) ++m.within_rounding;
        if (ref_hit != results[i].hit) {
            ++m.wrong;
            if (clear) ++m.wrong_clear;
            if (results[i].hit) ++m.false_hits;
        } else if (ref_hit) {
            errors.push_back(relative(results[i].h.t, ref.t));
        }
    }
    summarise_t_errors(errors, m);
    return m;
}

template <class S>
std::vector<Ray> secondary_rays(const std::vector<Case<S>>& cases, const std::vector<Result>& primary, bool into,
                                std::vector<std::size_t>& kept) {
    std::vector<Ray> rays;
    kept.clear();
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (!primary[i].hit) continue;
        const collision::RayHit& h = primary[i].h;
        // "Out" is the outside of a closed shape, or the side a flat shape was hit from.
        float out_side = 1.0f;
        if (!shape_is_closed<S>()) out_side = glm::dot(cases[i].ray.dir, h.normal) < 0.0f ? 1.0f : -1.0f;
        glm::vec3 w = cases[i].secondary_dir;
        const float side = glm::dot(w, h.normal) * out_side;
        if (side == 0.0f || !std::isfinite(side)) continue;
        if ((side > 0.0f) == into) w = -w;
        rays.push_back(Ray{offset_origin(h.point, h.point_error, h.normal, w), w});
        kept.push_back(i);
    }
    return rays;
}

template <class S>
bool is_self_hit(const S& shape, const Ray& secondary, bool into, const Result& r) {
    if (!r.hit) return false;
    // Leaving a convex shape or any flat one, nothing else is there to hit.
    if (!into || !shape_is_closed<S>()) return true;
    // Into a convex shape: the right hit is the far side; anything before half of it is the
    // surface the ray started on.
    const RefSpan span = reference_span(widen(secondary), shape);
    if (!span.meets) return true;
    return static_cast<long double>(r.h.t) < 0.5L * span.t1;
}

template <class S>
Metrics run_closed_meshes(const Variant<S>& variant, const std::vector<ClosedMeshCase<S>>& meshes) {
    Metrics m;
    m.variant = variant.name;
    m.family = family_name(Family::Edges);
    std::vector<double> errors;
    std::vector<Result> out;
    for (const auto& mesh : meshes) {
        m.seconds += variant.mesh(mesh.faces, mesh.rays, out);
        for (std::size_t i = 0; i < mesh.rays.size(); ++i) {
            ++m.rays;
            // Every ray starts strictly inside: the exact answer is always a hit, at the nearest
            // face the line meets (faces at a vertex all give that same t, ambiguous or not).
            const LRay r = widen(mesh.rays[i]);
            long double t_ref = std::numeric_limits<long double>::infinity();
            for (const S& f : mesh.faces) {
                const RefSpan span = reference_span(r, f);
                if (span.meets && span.t0 > r.tmin) t_ref = std::min(t_ref, span.t0);
            }
            if (!out[i].hit) {
                ++m.leaks;
                ++m.wrong;
            } else if (std::isfinite(t_ref)) {
                errors.push_back(relative(out[i].h.t, t_ref));
            }
        }
    }
    summarise_t_errors(errors, m);
    m.shape = shape_name<S>();
    // Throughput counts ray-face tests here (brute force over the mesh).
    if (!meshes.empty()) m.seconds /= double(meshes.front().faces.size());
    return m;
}

namespace {

template <class S>
Metrics run_cases(const Variant<S>& v, Family f, const std::vector<Case<S>>& cases) {
    std::vector<S> shapes;
    std::vector<Ray> rays;
    for (const auto& c : cases) {
        shapes.push_back(c.shape);
        rays.push_back(c.ray);
    }
    std::vector<Result> out;
    Metrics m;
    if (f == Family::SurfaceIn || f == Family::SurfaceOut) {
        const bool into = f == Family::SurfaceIn;
        v.batch(shapes, rays, out);
        std::vector<std::size_t> kept;
        const std::vector<Ray> secondary = secondary_rays(cases, out, into, kept);
        std::vector<S> kept_shapes;
        for (std::size_t i : kept) kept_shapes.push_back(cases[i].shape);
        std::vector<Result> second_out;
        const double seconds = v.batch(kept_shapes, secondary, second_out);
        m = score(kept_shapes, secondary, second_out);
        m.seconds = seconds;
        for (std::size_t i = 0; i < secondary.size(); ++i) {
            if (is_self_hit(kept_shapes[i], secondary[i], into, second_out[i])) ++m.self_hits;
        }
    } else {
        const double seconds = v.batch(shapes, rays, out);
        m = score(shapes, rays, out);
        m.seconds = seconds;
        // Every edges ray starts inside a closed shape: each miss is a leak.
        if (f == Family::Edges) m.leaks = m.wrong - m.false_hits;
    }
    m.shape = shape_name<S>();
    m.variant = v.name;
    m.family = family_name(f);
    return m;
}

}  // namespace

template <class S>
Metrics run_family(const Variant<S>& v, Family f, std::size_t n, std::uint64_t seed) {
    if constexpr (std::is_same_v<S, collision::Triangle> || std::is_same_v<S, collision::Quad>) {
        if (f == Family::Edges) return run_closed_meshes(v, make_closed_meshes<S>(n, seed));
    }
    return run_cases(v, f, make_cases<S>(f, n, seed));
}

template <class S>
std::vector<Metrics> run_shape(const std::vector<Variant<S>>& variants, std::size_t n, std::uint64_t seed) {
    std::vector<Metrics> rows;
    for (Family f : all_families) {
        if (!family_applies<S>(f)) continue;
        if constexpr (std::is_same_v<S, collision::Triangle> || std::is_same_v<S, collision::Quad>) {
            if (f == Family::Edges) {
                const auto meshes = make_closed_meshes<S>(n, seed);
                for (const auto& v : variants) {
                    if (v.mesh) rows.push_back(run_closed_meshes(v, meshes));
                }
                continue;
            }
        }
        const std::vector<Case<S>> cases = make_cases<S>(f, n, seed);
        for (const auto& v : variants) rows.push_back(run_cases(v, f, cases));
    }
    return rows;
}

#define SWEEPTRACE_ACCURACY_RUN(S)                                                                                  \
    template Variant<S> variant_of<S>(std::string, bool (*)(const Ray&, const S&, collision::RayHit&));             \
    template Metrics run_closed_meshes<S>(const Variant<S>&, const std::vector<ClosedMeshCase<S>>&);               \
    template Metrics score<S>(const std::vector<S>&, const std::vector<Ray>&, const std::vector<Result>&);         \
    template std::vector<Metrics> run_shape<S>(const std::vector<Variant<S>>&, std::size_t, std::uint64_t);      \
    template Metrics run_family<S>(const Variant<S>&, Family, std::size_t, std::uint64_t);
SWEEPTRACE_ACCURACY_RUN(collision::Sphere)
SWEEPTRACE_ACCURACY_RUN(collision::Aabb)
SWEEPTRACE_ACCURACY_RUN(collision::Cylinder)
SWEEPTRACE_ACCURACY_RUN(collision::Capsule)
SWEEPTRACE_ACCURACY_RUN(collision::OrientedCapsule)
SWEEPTRACE_ACCURACY_RUN(collision::Ellipsoid)
SWEEPTRACE_ACCURACY_RUN(collision::Plane)
SWEEPTRACE_ACCURACY_RUN(collision::Disk)
SWEEPTRACE_ACCURACY_RUN(collision::Quad)
SWEEPTRACE_ACCURACY_RUN(collision::Triangle)
#undef SWEEPTRACE_ACCURACY_RUN

}  // namespace sweeptrace::accuracy

#include "raytracer/accuracy/structures.hpp"

#include <cstdio>
#include <functional>
#include <memory>
#include <random>

#include <glm/geometric.hpp>

#include "collision/intersect.hpp"
#include "raytracer/accel/embree_reference.hpp"
#include "raytracer/accel/wide_mesh_bvh.hpp"
#include "raytracer/accel/mesh_hashed_grid.hpp"
#include "raytracer/accel/mesh_ray_octants.hpp"
#include "raytracer/accuracy/cases.hpp"
#include "raytracer/accuracy/thread_timer.hpp"

namespace sweeptrace::accuracy {

using collision::Ray;

namespace {


struct Traced {
    bool hit = false;
    std::uint32_t triangle = 0;
};

using Tracer = std::function<Traced(const Ray&)>;

// The tracer of a structure with intersect(ray, hit, triangle).
template <class T>
Tracer tracer_of(std::shared_ptr<T> s, std::shared_ptr<void>& keep) {
    keep = s;
    return [s](const Ray& r) {
        Traced out;
        collision::RayHit h;
        out.hit = s->intersect(r, h, out.triangle);
        return out;
    };
}

// Builds one structure (timed by the caller) and returns its tracer; `keep` owns what it uses.
Tracer build(const std::string& name, const collision::TriangleMesh& mesh, std::shared_ptr<void>& keep) {
    if (name == "brute-force") {
        return [&mesh](const Ray& ray) {
            Traced out;
            collision::RayHit h;
            Ray r = ray;
            for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
                if (collision::intersect(r, mesh.triangle(t), h)) {
                    r.tmax = h.t;
                    out = {true, t};
                }
            }
            return out;
        };
    }
    if (name == "octants") return tracer_of(std::make_shared<MeshRayOctants>(mesh), keep);
    if (name == "hashed-grid") return tracer_of(std::make_shared<MeshHashedGrid>(mesh), keep);
    if (name == "bvh") return tracer_of(std::make_shared<WideMeshBvh>(mesh), keep);  // the renderer's traversal
    auto s = std::make_shared<EmbreeTriangles>(mesh, false);
    keep = s;
    return [s](const Ray& r) {
        Traced out;
        EmbreeTriangleHit h;
        out.hit = s->intersect(r, h);
        out.triangle = h.primitive;
        return out;
    };
}

}  // namespace

std::vector<StructureRow> measure_structures(int min_level, int max_level, std::size_t max_rays,
                                             double budget_seconds, std::uint64_t seed) {
    std::vector<StructureRow> rows;
    for (int level = min_level; level <= max_level; ++level) {
        const collision::TriangleMesh mesh = icosphere_mesh(level, glm::vec3(0.125f, -0.25f, 0.375f), 1.0f);
        CaseRng rng(seed + std::uint64_t(level));
        std::uniform_real_distribution<float> u(-1.0f, 1.0f);
        std::vector<Ray> rays(max_rays);
        for (auto& r : rays) {
            glm::vec3 dir(u(rng), u(rng), u(rng));
            while (glm::length(dir) < 0.1f) dir = glm::vec3(u(rng), u(rng), u(rng));
            const glm::vec3 origin = glm::vec3(0.125f, -0.25f, 0.375f) + 3.0f * glm::normalize(dir);
            const glm::vec3 target(u(rng), u(rng), u(rng));
            r = Ray{origin, target - origin};
        }
        std::vector<Traced> bvh_results;
        // The BVH first: its results are what the others are compared with.
        for (const char* name : {"bvh", "embree", "hashed-grid", "octants", "brute-force"}) {
            std::shared_ptr<void> keep;
            const double start = wall_seconds();
            const Tracer trace = build(name, mesh, keep);
            StructureRow row;
            row.structure = name;
            row.triangles = mesh.triangle_count();
            row.build_seconds = wall_seconds() - start;
            std::vector<Traced> results;
            const double trace_start = thread_seconds();
            for (std::size_t i = 0; i < rays.size(); ++i) {
                results.push_back(trace(rays[i]));
                if ((i & 15) == 15 && thread_seconds() - trace_start > budget_seconds) break;
            }
            const double elapsed = thread_seconds() - trace_start;
            row.rays = results.size();
            row.mrays_per_s = elapsed > 0.0 ? double(row.rays) / elapsed * 1e-6 : 0.0;
            if (row.structure == "bvh") bvh_results = results;
            for (std::size_t i = 0; i < results.size() && i < bvh_results.size(); ++i) {
                if (results[i].hit != bvh_results[i].hit ||
                    (results[i].hit && results[i].triangle != bvh_results[i].triangle)) {
                    ++row.mismatches;
                }
            }
            rows.push_back(row);
        }
    }
    return rows;
}

void write_structures_csv(std::ostream& out, const std::vector<StructureRow>& rows) {
    out << "structure,triangles,build_s,rays,mrays_per_s,mismatches_vs_bvh\n";
    char buf[256];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "%s,%zu,%.6g,%zu,%.6g,%zu\n", r.structure.c_str(), r.triangles, r.build_seconds,
                      r.rays, r.mrays_per_s, r.mismatches);
        out << buf;
    }
}

void write_structures_markdown(std::ostream& out, const std::vector<StructureRow>& rows) {
    out << "| structure | triangles | build ms | rays | Mrays/s (1 thread) | differs from BVH |\n"
           "|---|---:|---:|---:|---:|---:|\n";
    char buf[256];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "| %s | %zu | %.3g | %zu | %.3g | %zu |\n", r.structure.c_str(), r.triangles,
                      1e3 * r.build_seconds, r.rays, r.mrays_per_s, r.mismatches);
        out << buf;
    }
}

}  // namespace sweeptrace::accuracy

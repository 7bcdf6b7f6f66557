#include "raytracer/accuracy/mesh_compare.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <random>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"
#include "collision/intersect.hpp"
#include "collision/mesh_boxes.hpp"
#include "raytracer/accel/embree_reference.hpp"
#include "raytracer/accel/wide_mesh_bvh.hpp"
#include "raytracer/accuracy/cases.hpp"
#include "raytracer/accuracy/reference.hpp"
#include "raytracer/accuracy/thread_timer.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/obj_loader.hpp"

namespace sweeptrace::accuracy {

using collision::Ray;
using glm::vec3;

namespace {


// Vertices identified by position, so a loader's duplicated vertices (one per normal) still
// share their edges.
struct PositionKeyHash {
    std::size_t operator()(const std::array<float, 3>& k) const {
        std::size_t h = 0;
        for (float f : k) h = h * 1000003u ^ std::hash<float>{}(f);
        return h;
    }
};

class EdgeMap {
public:
    explicit EdgeMap(const collision::TriangleMesh& mesh) : mesh_(mesh) {
        std::unordered_map<std::array<float, 3>, std::uint32_t, PositionKeyHash> ids;
        ids_.resize(mesh.vertices.size());
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            const vec3& p = mesh.vertices[v];
            ids_[v] = ids.emplace(std::array<float, 3>{p.x, p.y, p.z}, std::uint32_t(ids.size())).first->second;
        }
        for (std::uint32_t f = 0; f < mesh.indices.size(); ++f) {
            for (int e = 0; e < 3; ++e) faces_[key(f, e)].push_back(f);
        }
    }
    // Edge e of face f joins corners e+1 and e+2 (opposite corner e, as barycentric e).
    std::uint64_t key(std::uint32_t f, int e) const {
        const glm::uvec3& tri = mesh_.indices[f];
        std::uint64_t a = ids_[tri[(e + 1) % 3]], b = ids_[tri[(e + 2) % 3]];
        if (a > b) std::swap(a, b);
        return a << 32 | b;
    }
    const std::vector<std::uint32_t>& faces(std::uint32_t f, int e) const { return faces_.at(key(f, e)); }
    bool closed() const {
        return std::all_of(faces_.begin(), faces_.end(), [](const auto& kv) { return kv.second.size() == 2; });
    }

private:
    const collision::TriangleMesh& mesh_;
    std::vector<std::uint32_t> ids_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> faces_;
};

struct Hit {
    bool hit = false;
    float t = 0.0f;
    std::uint32_t prim = 0;
};

struct Method {
    std::string name;
    double build_seconds = 0.0;
    std::function<Hit(const Ray&)> trace;
};

std::vector<Method> make_methods(const collision::TriangleMesh& mesh, std::vector<std::unique_ptr<WideMeshBvh>>& bvhs,
                                 std::vector<std::unique_ptr<EmbreeTriangles>>& embrees) {
    std::vector<Method> methods;
    double start = wall_seconds();
    bvhs.push_back(std::make_unique<WideMeshBvh>(mesh));  // the renderer's own traversal
    const WideMeshBvh* bvh = bvhs.back().get();
    methods.push_back({"native", wall_seconds() - start, [bvh](const Ray& r) {
                           Hit h;
                           collision::RayHit rh;
                           h.hit = bvh->intersect(r, rh, h.prim);
                           h.t = rh.t;
                           return h;
                       }});
    for (bool robust : {false, true}) {
        start = wall_seconds();
        embrees.push_back(std::make_unique<EmbreeTriangles>(mesh, robust));
        const EmbreeTriangles* e = embrees.back().get();
        methods.push_back({robust ? "embree-robust" : "embree", wall_seconds() - start, [e](const Ray& r) {
                               Hit h;
                               EmbreeTriangleHit eh;
                               h.hit = e->intersect(r, eh);
                               h.t = eh.t;
                               h.prim = eh.primitive;
                               return h;
                           }});
    }
    return methods;
}


// A point of the mesh to aim at: a vertex, or a point of an edge (within rounding).
vec3 mesh_target(CaseRng& rng, const collision::TriangleMesh& mesh, bool vertex) {
    const collision::Triangle t = mesh.triangle(std::uniform_int_distribution<std::size_t>(0, mesh.triangle_count() - 1)(rng));
    if (vertex) return t.a;
    const float s = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    return t.a + s * (t.b - t.a);
}

// Where does the ray meet triangle `prim`? Classified by its long double barycentrics: within
// `tol` of 0 means on that edge as far as a float test can tell. The tests compute edge
// functions from origin-relative vertices, whose rounding is about eps |v - o| each, i.e. eps
// times distance / triangle size relative to the barycentrics; 64 such roundings (2^-18) cover
// the error bounds of both the watertight test and Embree's.
enum class Where { Silhouette, SharedEdge, SharedVertex, OpenEdge, Other };

Where classify(const Ray& ray, const collision::TriangleMesh& mesh, const EdgeMap& edges, std::uint32_t prim) {
    const collision::Triangle t = mesh.triangle(prim);
    const LVec3 o = widen(ray.origin), d = widen(ray.dir);
    const LVec3 p[3] = {widen(t.a) - o, widen(t.b) - o, widen(t.c) - o};
    long double w[3];
    for (int i = 0; i < 3; ++i) w[i] = glm::dot(glm::cross(p[(i + 1) % 3], p[(i + 2) % 3]), d);
    const long double sum = w[0] + w[1] + w[2];
    if (sum == 0.0L) return Where::Other;
    const long double size = std::max({glm::length(t.b - t.a), glm::length(t.c - t.b), glm::length(t.a - t.c)});
    const LVec3 centroid = (p[0] + p[1] + p[2]) / 3.0L;
    const long double dist = std::sqrt(glm::dot(centroid, centroid));
    const long double tol = std::ldexp(1.0L, -18) * (1.0L + dist / std::max(size, 1e-30L));
    int near = 0, edge = -1;
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(w[i] / sum) <= tol) {
            ++near;
            edge = i;
        }
    }
    if (near >= 2) return Where::SharedVertex;
    if (near == 0) return Where::Other;
    const auto& faces = edges.faces(prim, edge);
    if (faces.size() < 2) return Where::OpenEdge;
    const std::uint32_t other = faces[0] == prim ? faces[1] : faces[0];
    const collision::Triangle u = mesh.triangle(other);
    const vec3 n1 = glm::cross(t.b - t.a, t.c - t.a), n2 = glm::cross(u.b - u.a, u.c - u.a);
    const float s1 = glm::dot(n1, ray.dir), s2 = glm::dot(n2, ray.dir);
    return s1 * s2 < 0.0f ? Where::Silhouette : Where::SharedEdge;
}

void count(MeshComparison& c, Where w) {
    switch (w) {
        case Where::Silhouette: ++c.silhouette; break;
        case Where::SharedEdge: ++c.shared_edge; break;
        case Where::SharedVertex: ++c.shared_vertex; break;
        case Where::OpenEdge: ++c.open_edge; break;
        case Where::Other: ++c.other; break;
    }
}

// Points strictly inside a closed mesh, decided by the long double reference alone (not by a
// method under test): along three random directions the number of triangles the ray crosses is
// odd, and no crossing is within the reference band of an edge (such a point is skipped). The
// conservative slab test only skips triangles the line cannot meet.
std::vector<vec3> inside_points(CaseRng& rng, const collision::TriangleMesh& mesh, const collision::Bounds3& box,
                                std::size_t wanted) {
    std::vector<collision::Bounds3> boxes(mesh.triangle_count());
    for (std::size_t f = 0; f < boxes.size(); ++f) boxes[f] = collision::triangle_bounds(mesh, f);
    std::vector<vec3> points;
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int attempt = 0; attempt < 2000 && points.size() < wanted; ++attempt) {
        const vec3 p = box.lo + (box.hi - box.lo) * vec3(u(rng), u(rng), u(rng));
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
            const Ray r{p, unit_vector(rng)};
            const vec3 inv = vec3(1.0f) / r.dir;
            int crossings = 0;
            for (std::size_t f = 0; f < boxes.size() && inside; ++f) {
                float t0 = 0.0f, t1 = 0.0f;
                if (!collision::intersect_slab(r, inv, boxes[f].lo, boxes[f].hi, t0, t1)) continue;
                const RefSpan span = reference_span(widen(r), mesh.triangle(f));
                if (span.ambiguous) inside = false;
                else if (span.meets && span.t0 > 0.0L) ++crossings;
            }
            inside = inside && crossings % 2 == 1;
        }
        if (inside) points.push_back(p);
    }
    return points;
}

template <class T>
void summarise(std::vector<T>& v, double& median, double& p99, double& max) {
    if (v.empty()) return;
    std::sort(v.begin(), v.end());
    median = v[v.size() / 2];
    p99 = v[std::min(v.size() - 1, std::size_t(0.99 * double(v.size())))];
    max = v.back();
}

}  // namespace

bool is_closed(const collision::TriangleMesh& mesh) { return EdgeMap(mesh).closed(); }

std::vector<NamedMesh> load_accuracy_meshes(const std::string& dir) {
    if (!std::filesystem::is_directory(dir)) throw InputError(dir + ": not a directory (--meshes wants ../shared/meshes)");
    std::vector<NamedMesh> meshes;
    for (const char* file : {"stanford-bunny.obj", "ogre.obj", "nefertiti.obj", "fandisk.obj", "spot.obj", "cow.obj",
                             "teapot.obj", "suzanne.obj"}) {
        const std::filesystem::path path = std::filesystem::path(dir) / file;
        if (!std::filesystem::exists(path)) continue;
        NamedMesh m;
        m.name = path.stem().string();
        m.mesh = load_obj(path).triangles;
        m.closed = is_closed(m.mesh);
        meshes.push_back(std::move(m));
    }
    for (int level : {3, 6}) {
        NamedMesh m;
        m.name = "icosphere-" + std::to_string(20 << (2 * level));
        m.mesh = icosphere_mesh(level, vec3(0.125f, -0.25f, 0.375f), 1.0f);
        m.closed = is_closed(m.mesh);
        meshes.push_back(std::move(m));
    }
    return meshes;
}

MeshReport compare_meshes(const std::vector<NamedMesh>& meshes, std::size_t rays_per_mesh,
                          std::size_t inside_rays_per_mesh, std::uint64_t seed) {
    MeshReport report;
    for (const NamedMesh& nm : meshes) {
        const collision::TriangleMesh& mesh = nm.mesh;
        if (mesh.triangle_count() == 0) continue;
        CaseRng rng(seed ^ std::hash<std::string>{}(nm.name));
        std::vector<std::unique_ptr<WideMeshBvh>> bvhs;
        std::vector<std::unique_ptr<EmbreeTriangles>> embrees;
        const std::vector<Method> methods = make_methods(mesh, bvhs, embrees);
        const EdgeMap edges(mesh);
        const collision::Bounds3 box = collision::mesh_bounds(mesh);
        const vec3 centre = box.center();
        const float radius = 0.5f * glm::length(box.hi - box.lo);

        // Outside rays: half at random points of the box, a quarter each at vertices and edges.
        std::vector<Ray> rays(rays_per_mesh);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const vec3 origin = centre + unit_vector(rng) * (3.0f * radius);
            vec3 target;
            const float kind = u(rng);
            if (kind < 0.5f) target = box.lo + (box.hi - box.lo) * vec3(u(rng), u(rng), u(rng));
            else target = mesh_target(rng, mesh, kind < 0.75f);
            rays[i] = Ray{origin, target - origin};
        }
        std::vector<std::vector<Hit>> results(methods.size(), std::vector<Hit>(rays.size()));
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const double start = thread_seconds();
            for (std::size_t i = 0; i < rays.size(); ++i) results[m][i] = methods[m].trace(rays[i]);
            const double s = thread_seconds() - start;
            MeshMethod row;
            row.mesh = nm.name;
            row.method = methods[m].name;
            row.triangles = mesh.triangle_count();
            row.rays = rays.size();
            row.build_seconds = methods[m].build_seconds;
            row.mrays_per_s = s > 0.0 ? double(rays.size()) / s * 1e-6 : 0.0;
            report.methods.push_back(row);
        }
        const std::pair<int, int> pairs[] = {{0, 1}, {0, 2}, {1, 2}};
        for (auto [a, b] : pairs) {
            MeshComparison c;
            c.mesh = nm.name;
            c.a = methods[a].name;
            c.b = methods[b].name;
            c.triangles = mesh.triangle_count();
            c.rays = rays.size();
            std::vector<double> dt;
            for (std::size_t i = 0; i < rays.size(); ++i) {
                const Hit& ha = results[a][i];
                const Hit& hb = results[b][i];
                if (ha.hit != hb.hit) {
                    ++c.hit_miss;
                    count(c, classify(rays[i], mesh, edges, ha.hit ? ha.prim : hb.prim));
                } else if (ha.hit) {
                    dt.push_back(std::fabs(double(ha.t) - double(hb.t)) / std::max(double(hb.t), 1e-30));
                    if (ha.prim != hb.prim) {
                        ++c.primitive;
                        count(c, classify(rays[i], mesh, edges, ha.prim));
                    }
                }
            }
            c.t_scored = dt.size();
            summarise(dt, c.t_median, c.t_p99, c.t_max);
            report.comparisons.push_back(c);
        }

        if (!nm.closed || inside_rays_per_mesh == 0) continue;
        const std::vector<vec3> inside = inside_points(rng, mesh, box, 32);
        if (inside.empty()) continue;
        std::vector<Ray> inner(inside_rays_per_mesh);
        for (auto& r : inner) {
            const vec3 o = inside[std::uniform_int_distribution<std::size_t>(0, inside.size() - 1)(rng)];
            r = Ray{o, mesh_target(rng, mesh, u(rng) < 0.5f) - o};
        }
        for (std::size_t m = 0; m < methods.size(); ++m) {
            MeshMethod& row = report.methods[report.methods.size() - methods.size() + m];
            row.inside_rays = inner.size();
            for (const Ray& r : inner) {
                if (!methods[m].trace(r).hit) ++row.leaks;
            }
        }
    }
    return report;
}

namespace {
std::string fmt(double v, const char* f = "%.3g") {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}
}  // namespace

void write_mesh_markdown(std::ostream& out, const MeshReport& r) {
    out << "| mesh | triangles | method | build ms | Mrays/s (1 thread) | rays from inside | leaks |\n"
           "|---|---:|---|---:|---:|---:|---:|\n";
    for (const MeshMethod& m : r.methods) {
        out << "| " << m.mesh << " | " << m.triangles << " | " << m.method << " | " << fmt(1e3 * m.build_seconds)
            << " | " << fmt(m.mrays_per_s) << " | " << m.inside_rays << " | " << m.leaks << " |\n";
    }
    out << "\n| mesh | a | b | rays | hit/miss differ | triangle differs | t rel. diff median | p99 | max "
           "| silhouette | shared edge | shared vertex | open edge | other |\n"
           "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const MeshComparison& c : r.comparisons) {
        out << "| " << c.mesh << " | " << c.a << " | " << c.b << " | " << c.rays << " | " << c.hit_miss << " | "
            << c.primitive << " | " << fmt(c.t_median) << " | " << fmt(c.t_p99) << " | " << fmt(c.t_max) << " | "
            << c.silhouette << " | " << c.shared_edge << " | " << c.shared_vertex << " | " << c.open_edge << " | "
            << c.other << " |\n";
    }
}

void write_comparisons_csv(std::ostream& out, const std::vector<MeshComparison>& rows) {
    out << "mesh,a,b,triangles,rays,hit_miss,primitive,t_scored,t_rel_median,t_rel_p99,t_rel_max,silhouette,"
           "shared_edge,shared_vertex,open_edge,other\n";
    for (const MeshComparison& c : rows) {
        out << c.mesh << ',' << c.a << ',' << c.b << ',' << c.triangles << ',' << c.rays << ',' << c.hit_miss << ','
            << c.primitive << ',' << c.t_scored << ',' << fmt(c.t_median, "%.6g") << ',' << fmt(c.t_p99, "%.6g")
            << ',' << fmt(c.t_max, "%.6g") << ',' << c.silhouette << ',' << c.shared_edge << ',' << c.shared_vertex
            << ',' << c.open_edge << ',' << c.other << '\n';
    }
}

void write_methods_csv(std::ostream& out, const std::vector<MeshMethod>& rows) {
    out << "mesh,method,triangles,rays,build_s,mrays_per_s,inside_rays,leaks\n";
    for (const MeshMethod& m : rows) {
        out << m.mesh << ',' << m.method << ',' << m.triangles << ',' << m.rays << ',' << fmt(m.build_seconds, "%.6g")
            << ',' << fmt(m.mrays_per_s, "%.4g") << ',' << m.inside_rays << ',' << m.leaks << '\n';
    }
}

}  // namespace sweeptrace::accuracy

#pragma once
// Meshes against Embree: the native BVH with the watertight triangle test against Embree with
// default flags and with RTC_SCENE_FLAG_ROBUST, on the same rays. Every disagreement is
// classified by where the ray meets the mesh; closed meshes also get rays from inside, where
// every miss is a leak.
#include <cstdint>
#include <string>
#include <vector>

#include "collision/mesh.hpp"

namespace sweeptrace::accuracy {

struct NamedMesh {
    std::string name;
    collision::TriangleMesh mesh;
    bool closed = false;  // every edge shared by exactly two triangles
};

// One comparison of two methods on one mesh's rays.
struct MeshComparison {
    std::string mesh, a, b;
    std::size_t triangles = 0, rays = 0;
    std::size_t hit_miss = 0;       // one hit, the other missed
    std::size_t primitive = 0;      // both hit, different triangles
    std::size_t t_scored = 0;       // both hit: relative t difference measured
    double t_median = 0.0, t_p99 = 0.0, t_max = 0.0;
    // Every disagreement (hit/miss or primitive) by where the ray meets the mesh:
    std::size_t silhouette = 0;     // near an edge whose two faces turn opposite ways to the ray
    std::size_t shared_edge = 0;    // near an edge between two faces turned the same way
    std::size_t shared_vertex = 0;  // near a vertex
    std::size_t open_edge = 0;      // near an edge of only one face (holes in open scans)
    std::size_t other = 0;          // none of these
};

// One method on one mesh: throughput, build time and (closed meshes) leaks of rays from inside.
struct MeshMethod {
    std::string mesh, method;
    std::size_t triangles = 0, rays = 0;
    double build_seconds = 0.0, mrays_per_s = 0.0;
    std::size_t inside_rays = 0, leaks = 0;
};

struct MeshReport {
    std::vector<MeshComparison> comparisons;
    std::vector<MeshMethod> methods;
};

// The shared meshes found in `dir` (those of ../shared/meshes/README.md; missing files are
// skipped) plus procedural icospheres. Throws InputError when `dir` is not a directory.
std::vector<NamedMesh> load_accuracy_meshes(const std::string& dir);

// Adjacency: is every edge (by vertex position) shared by exactly two triangles?
bool is_closed(const collision::TriangleMesh& mesh);

MeshReport compare_meshes(const std::vector<NamedMesh>& meshes, std::size_t rays_per_mesh,
                          std::size_t inside_rays_per_mesh, std::uint64_t seed);

void write_mesh_markdown(std::ostream& out, const MeshReport& report);
void write_comparisons_csv(std::ostream& out, const std::vector<MeshComparison>& rows);
void write_methods_csv(std::ostream& out, const std::vector<MeshMethod>& rows);

}  // namespace sweeptrace::accuracy

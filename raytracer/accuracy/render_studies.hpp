#pragma once
// Studies that render: "model no more than a scene needs" (the same object analytic and
// tessellated) and convergence (image error against time, BSDF-only against NEE+MIS, native
// BVH against Embree). Benchmarks: they print and chart, they assert nothing.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace sweeptrace::accuracy {

struct TessellationRow {
    std::string shape, representation, accel;  // representation: "analytic" or "mesh"
    std::size_t triangles = 0;                 // 0 for analytic
    double seconds = 0.0;                      // build + render, CPU seconds of all threads
    double rmse = 0.0;                         // linear RMSE against the analytic render, same seed and spp
    double noise_rmse = 0.0;                   // the analytic render's own RMSE against a converged one
    std::size_t accel_bytes = 0;               // the acceleration structure (not the scene data)
    std::size_t mesh_bytes = 0;                // vertices, normals and indices of the mesh
};

// Sphere, cylinder, capsule, ellipsoid under a sky, each analytic and tessellated with
// 1e2 .. 10^max_exponent triangles, native BVH and Embree. `size` pixels wide (3:4 image).
std::vector<TessellationRow> tessellation_study(int size, int spp, int reference_spp, int max_exponent,
                                                unsigned seed);

struct ConvergenceRow {
    std::string scene, sampling, accel;  // sampling: "nee-mis" or "bsdf-only"
    int spp = 0;
    double seconds = 0.0;  // build + render, CPU seconds of all threads
    double rmse = 0.0;     // linear RMSE against the reference render
};

// For each scene file: a NEE+MIS reference at reference_spp, then 1, 2, 4 .. max_spp for both
// samplings and both accelerators, at `size` pixels wide (the scene's aspect kept).
std::vector<ConvergenceRow> convergence_study(const std::vector<std::filesystem::path>& scenes, int size,
                                              int max_spp, int reference_spp);

void write_tessellation_csv(std::ostream& out, const std::vector<TessellationRow>& rows);
void write_tessellation_markdown(std::ostream& out, const std::vector<TessellationRow>& rows);
void write_convergence_csv(std::ostream& out, const std::vector<ConvergenceRow>& rows);
void write_convergence_markdown(std::ostream& out, const std::vector<ConvergenceRow>& rows);

}  // namespace sweeptrace::accuracy

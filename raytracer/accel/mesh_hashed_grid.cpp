#include "raytracer/accel/mesh_hashed_grid.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "collision/intersect.hpp"
#include "collision/mesh_boxes.hpp"

namespace sweeptrace {

namespace {

// Cells about one triangle across: a triangle then touches a handful of cells and a cell holds
// a handful of triangles, the balance the thesis describes (S too large: everything in one
// cell; too small: memory).
float mean_edge(const collision::TriangleMesh& mesh) {
    double sum = 0.0;
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
        const collision::Triangle t = mesh.triangle(i);
        sum += glm::length(t.b - t.a) + glm::length(t.c - t.b) + glm::length(t.a - t.c);
    }
    const double mean = mesh.triangle_count() ? sum / (3.0 * double(mesh.triangle_count())) : 1.0;
    return mean > 0.0 ? float(mean) : 1.0f;
}

}  // namespace

MeshHashedGrid::MeshHashedGrid(const collision::TriangleMesh& mesh, float cell_size)
    : mesh_(&mesh), grid_(cell_size > 0.0f ? cell_size : mean_edge(mesh)) {
    for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
        const collision::Bounds3 box = collision::triangle_bounds(mesh, t);
        bounds_.extend(box);
        grid_.insert(t, box.lo, box.hi);
    }
}

bool MeshHashedGrid::intersect(const collision::Ray& ray, collision::RayHit& hit, std::uint32_t& triangle) const {
    if (bounds_.empty()) return false;
    const glm::vec3 inv = glm::vec3(1.0f) / ray.dir;
    float t_enter = 0.0f, t_exit = 0.0f;
    if (!collision::intersect_slab(ray, inv, bounds_.lo, bounds_.hi, t_enter, t_exit)) return false;
    // The walk in double: cell boundaries k S and the per-axis crossing times are then exact
    // enough that the walk never skips a cell a float rounding would put the ray in.
    const double s = grid_.cell_size();
    const glm::dvec3 o(ray.origin), d(ray.dir);
    const glm::dvec3 start = o + d * double(t_enter);
    const glm::ivec3 lo_cell = grid_.cell_of(bounds_.lo), hi_cell = grid_.cell_of(bounds_.hi);
    glm::ivec3 cell = glm::clamp(grid_.cell_of(glm::vec3(start)), lo_cell, hi_cell);
    glm::ivec3 step;
    glm::dvec3 t_next, t_delta;
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (d[k] > 0.0) {
            step[k] = 1;
            t_next[k] = ((cell[k] + 1) * s - o[k]) / d[k];
            t_delta[k] = s / d[k];
        } else if (d[k] < 0.0) {
            step[k] = -1;
            t_next[k] = (cell[k] * s - o[k]) / d[k];
            t_delta[k] = -s / d[k];
        } else {
            step[k] = 0;
            t_next[k] = inf;
            t_delta[k] = inf;
        }
    }
    collision::Ray r = ray;
    bool found = false;
    for (;;) {
        for (std::uint32_t t : grid_.cell(cell)) {
            if (collision::intersect(r, mesh_->triangle(t), hit)) {
                r.tmax = hit.t;
                triangle = t;
                found = true;
            }
        }
        const int axis = t_next.x < t_next.y ? (t_next.x < t_next.z ? 0 : 2) : (t_next.y < t_next.z ? 1 : 2);
        // A hit before this cell's exit cannot be beaten by a later cell.
        if (found && double(r.tmax) <= t_next[axis]) return true;
        if (t_next[axis] > double(t_exit)) return found;
        cell[axis] += step[axis];
        if (cell[axis] < lo_cell[axis] || cell[axis] > hi_cell[axis]) return found;
        t_next[axis] += t_delta[axis];
    }
}

}  // namespace sweeptrace

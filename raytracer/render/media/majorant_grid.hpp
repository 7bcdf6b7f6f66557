#pragma once
// A coarse grid of density bounds over a grid medium's box, walked along a ray by a 3D DDA
// (Amanatides and Woo 1987; pbrt-v4's MajorantGrid and DDAMajorantIterator are the model).
// Delta and ratio tracking sample collisions at the rate of a majorant, a bound on the medium's
// extinction; with one bound for the whole medium, sparse smoke costs what its densest voxel would
// everywhere. Here each of res^3 cells holds the largest density sample whose trilinear support
// reaches into it, so the walk gives piecewise-constant bounds that are tight where the medium is
// thin, and no collisions at all in empty cells.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace sweeptrace {

class MajorantGrid {
public:
    MajorantGrid() = default;
    // Bounds of the density samples `density` (nx x ny x nz, x fastest) over res^3 cells of the
    // unit cube [0, 1]^3, in which sample (i, j, k) sits at ((i + 0.5) / nx, ...).
    MajorantGrid(const std::vector<float>& density, int nx, int ny, int nz, int res);

    int resolution() const { return res_; }
    float at(int x, int y, int z) const { return max_[(static_cast<std::size_t>(z) * res_ + y) * res_ + x]; }

    // Calls f(t0, t1, bound) for each cell the ray o + t d (grid space: the unit cube) crosses
    // within [tmin, tmax], in order along the ray; stops when f returns false. Returns false then,
    // true when the walk reached the end.
    template <class F>
    bool walk(const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, F&& f) const;

private:
    int res_ = 0;
    std::vector<float> max_;
};

// The parameter range [t0, t1] of o + t d inside the unit cube, intersected with [t0, t1] as
// given; false if empty. (The slab test; an axis the ray runs parallel to either keeps the range
// or empties it.)
bool clip_to_unit_cube(const glm::vec3& o, const glm::vec3& d, float& t0, float& t1);

template <class F>
bool MajorantGrid::walk(const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, F&& f) const {
    if (!clip_to_unit_cube(o, d, tmin, tmax)) return true;
    const glm::vec3 entry = o + tmin * d;
    const float r = static_cast<float>(res_);
    int cell[3], step[3], limit[3];
    float next[3], delta[3];
    for (int a = 0; a < 3; ++a) {
        cell[a] = static_cast<int>(entry[a] * r);
        cell[a] = cell[a] < 0 ? 0 : cell[a] >= res_ ? res_ - 1 : cell[a];
        if (d[a] > 0.0f) {
            next[a] = tmin + ((static_cast<float>(cell[a] + 1) / r) - entry[a]) / d[a];
            delta[a] = 1.0f / (d[a] * r);
            step[a] = 1;
            limit[a] = res_;
        } else if (d[a] < 0.0f) {
            next[a] = tmin + ((static_cast<float>(cell[a]) / r) - entry[a]) / d[a];
            delta[a] = -1.0f / (d[a] * r);
            step[a] = -1;
            limit[a] = -1;
        } else {
            next[a] = tmax;  // never crossed: the segment ends first
            delta[a] = 0.0f;
            step[a] = 0;
            limit[a] = -2;
        }
    }
    float t = tmin;
    while (t < tmax) {
        const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
        const float exit = next[a] < tmax ? next[a] : tmax;
        if (exit > t && !f(t, exit, at(cell[0], cell[1], cell[2]))) return false;
        t = exit;
        if (step[a] == 0) break;  // the segment ended inside this cell
        cell[a] += step[a];
        if (cell[a] == limit[a]) break;
        next[a] += delta[a];
    }
    return true;
}

}  // namespace sweeptrace

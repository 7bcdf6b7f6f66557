#include "raytracer/render/media/majorant_grid.hpp"

#include <algorithm>
#include <cmath>

namespace sweeptrace {

MajorantGrid::MajorantGrid(const std::vector<float>& density, int nx, int ny, int nz, int res)
    : res_(res), max_(static_cast<std::size_t>(res) * res * res, 0.0f) {
    const int n[3] = {nx, ny, nz};
    // The samples whose trilinear support reaches into [lo, hi] along one axis: the lookup at x
    // blends samples floor(x n - 0.5) and the one after (pbrt-v4's SampledGrid::MaxValue).
    auto range = [&](int axis, int cell, int& first, int& last) {
        const float lo = static_cast<float>(cell) / static_cast<float>(res);
        const float hi = static_cast<float>(cell + 1) / static_cast<float>(res);
        first = std::max(static_cast<int>(std::floor(lo * static_cast<float>(n[axis]) - 0.5f)), 0);
        last = std::min(static_cast<int>(std::floor(hi * static_cast<float>(n[axis]) - 0.5f)) + 1, n[axis] - 1);
    };
    for (int z = 0; z < res; ++z) {
        int z0, z1;
        range(2, z, z0, z1);
        for (int y = 0; y < res; ++y) {
            int y0, y1;
            range(1, y, y0, y1);
            for (int x = 0; x < res; ++x) {
                int x0, x1;
                range(0, x, x0, x1);
                float m = 0.0f;
                for (int k = z0; k <= z1; ++k)
                    for (int j = y0; j <= y1; ++j)
                        for (int i = x0; i <= x1; ++i)
                            m = std::max(m, density[(static_cast<std::size_t>(k) * ny + j) * nx + i]);
                max_[(static_cast<std::size_t>(z) * res + y) * res + x] = m;
            }
        }
    }
}

bool clip_to_unit_cube(const glm::vec3& o, const glm::vec3& d, float& t0, float& t1) {
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0f) {
            if (o[a] < 0.0f || o[a] > 1.0f) return false;
            continue;
        }
        const float inv = 1.0f / d[a];
        float lo = (0.0f - o[a]) * inv, hi = (1.0f - o[a]) * inv;
        if (lo > hi) std::swap(lo, hi);
        t0 = std::max(t0, lo);
        t1 = std::min(t1, hi);
        if (t0 > t1) return false;
    }
    return t0 < t1;
}

}  // namespace sweeptrace

#pragma once
// A random path's densities for the MIS tests (test_render_bdpt.cpp, test_render_vcm.cpp): 1 to 8
// vertices after the light, densities log-uniform over four decades, delta vertices where a
// subpath would put them (a quarter of the inner vertices, with the densities next to them 0, as
// the walks store them), medium vertices (a fifth of the other inner vertices: no merge there,
// bidir_mis.hpp), the light hittable or not, joinable to the camera or not.
#include <cmath>
#include <random>

#include "raytracer/render/integrators/bidir_mis.hpp"

namespace sweeptrace::testing {

inline MisPath random_mis_path(std::mt19937& rng) {
    std::uniform_real_distribution<float> decade(-2.0f, 2.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    MisPath p;
    const int k = 1 + static_cast<int>(unit(rng) * 8.0f);
    p.reset(k, 0, k);  // the whole path, no tails: the explicit sums
    for (int i = 0; i <= k; ++i) {
        p.fl(i) = std::pow(10.0f, decade(rng));
        p.fc(i) = std::pow(10.0f, decade(rng));
    }
    p.emit0 = p.fl(0);
    for (int i = 1; i < k; ++i)
        if (unit(rng) < 0.25f) {
            p.delta(i) = 1;
            p.fl(i + 1) = 0.0f;
            p.fc(i - 1) = 0.0f;
        }
    for (int i = 1; i < k; ++i)
        if (!p.delta(i) && unit(rng) < 0.2f) p.medium(i) = 1;
    p.nee0 = std::pow(10.0f, decade(rng));
    p.light_hittable = unit(rng) < 0.7f;
    p.light_to_camera = unit(rng) < 0.7f;
    return p;
}

}  // namespace sweeptrace::testing

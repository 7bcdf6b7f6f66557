#pragma once
// A random path's densities for the MIS tests (test_render_bdpt.cpp, test_render_vcm.cpp): 1 to 8
// vertices after the light, densities log-uniform over four decades, delta vertices where a
// subpath would put them (a quarter of the inner vertices, with the densities next to them 0, as
// the walks store them), the light hittable or not, joinable to the camera or not.
#include <cmath>
#include <random>

#include "raytracer/render/integrators/bidir_mis.hpp"

namespace sweeptrace::testing {

inline MisPath random_mis_path(std::mt19937& rng) {
    std::uniform_real_distribution<float> decade(-2.0f, 2.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    MisPath p;
    p.k = 1 + static_cast<int>(unit(rng) * 8.0f);
    const auto size = static_cast<std::size_t>(p.k + 1);
    p.from_light.resize(size);
    p.from_camera.resize(size);
    p.delta.assign(size, 0);
    for (std::size_t i = 0; i < size; ++i) {
        p.from_light[i] = std::pow(10.0f, decade(rng));
        p.from_camera[i] = std::pow(10.0f, decade(rng));
    }
    for (int i = 1; i < p.k; ++i)
        if (unit(rng) < 0.25f) {
            p.delta[static_cast<std::size_t>(i)] = 1;
            p.from_light[static_cast<std::size_t>(i + 1)] = 0.0f;
            p.from_camera[static_cast<std::size_t>(i - 1)] = 0.0f;
        }
    p.nee0 = std::pow(10.0f, decade(rng));
    p.light_hittable = unit(rng) < 0.7f;
    p.light_to_camera = unit(rng) < 0.7f;
    return p;
}

}  // namespace sweeptrace::testing

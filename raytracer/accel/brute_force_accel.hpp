#pragma once
// Every object tested for every ray, meshes triangle by triangle: no structure at all. The
// reference the BVH and Embree are checked against, and the baseline of the speed charts.
#include <memory>

#include "raytracer/accel/accel.hpp"

namespace sweeptrace {

std::unique_ptr<Accel> make_brute_force_accel(const Scene& scene);

}  // namespace sweeptrace

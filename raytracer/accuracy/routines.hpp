#pragma once
// Every ray-shape routine the accuracy command measures, by shape, with its variants: the
// robust default of collision/, the thesis-faithful variant of collision/thesis/, and for
// triangles Embree's test (default and RTC_SCENE_FLAG_ROBUST).
#include <cstdint>
#include <string>
#include <vector>

#include "collision/shapes.hpp"
#include "raytracer/accuracy/run.hpp"

namespace sweeptrace::accuracy {

// Embree's triangle test as a variant: one scene per case / per closed mesh, default flags or
// RTC_SCENE_FLAG_ROBUST.
Variant<collision::Triangle> embree_triangle_variant(bool robust);

// Names accepted by run_routines' filter.
const std::vector<std::string>& routine_shape_names();

// All families for the shapes named in `shapes` (empty = all), `n` rays per family.
std::vector<Metrics> run_routines(const std::vector<std::string>& shapes, std::size_t n, std::uint64_t seed);

}  // namespace sweeptrace::accuracy

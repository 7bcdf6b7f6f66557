#pragma once
// Adding one's own ray-shape routine to the accuracy table (docs/accuracy-for-your-intersector.md,
// example in examples/custom_intersector.cpp). Register before calling run_routines; the routine
// is then measured like the built-in variants on every family of its shape, the secondary-ray
// families included (they spawn rays from the routine's own hits, so it must fill RayHit's t,
// point, normal and point_error; a zero point_error means "no error bound", offset by one ulp).
//
//   bool my_sphere(const collision::Ray& ray, const collision::Sphere& s, collision::RayHit& hit);
//   sweeptrace::accuracy::register_routine<collision::Sphere>("mine", &my_sphere);
//   const auto rows = sweeptrace::accuracy::run_routines({"sphere"}, 20000, 1);
//   sweeptrace::accuracy::write_markdown(std::cout, rows);
//
// Contract of the routine (the built-ins' contract): nearest hit with tmin < t < tmax, the exit
// point when the ray starts inside a closed shape; return false on a miss. Not thread-safe:
// register from one thread before measuring.
#include <string>
#include <vector>

#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "raytracer/accuracy/run.hpp"

namespace sweeptrace::accuracy {

template <class Shape>
using RoutineFn = bool (*)(const collision::Ray&, const Shape&, collision::RayHit&);

// Variants registered for this shape, in registration order.
template <class Shape>
std::vector<Variant<Shape>>& registered_variants() {
    static std::vector<Variant<Shape>> variants;
    return variants;
}

// A variant with its own batch (e.g. a SIMD or GPU routine timing its own loop): the general form.
template <class Shape>
void register_variant(Variant<Shape> variant) {
    registered_variants<Shape>().push_back(std::move(variant));
}

// A plain per-ray function: timed per batch on one thread like the built-ins.
template <class Shape>
void register_routine(std::string name, RoutineFn<Shape> fn) {
    register_variant<Shape>(variant_of<Shape>(std::move(name), fn));
}

}  // namespace sweeptrace::accuracy

#pragma once
// Runs intersector variants over the ray families and scores them against the long double
// reference: wrong hit/miss, relative t error, self-hits of secondary rays, leaks through closed
// meshes, and single-thread throughput on the same rays.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "raytracer/accuracy/cases.hpp"

namespace sweeptrace::accuracy {

struct Result {
    bool hit = false;
    collision::RayHit h;
};

// One row of the accuracy table.
struct Metrics {
    std::string shape, variant, family;
    std::size_t rays = 0;          // rays scored (secondary rays for the surface families)
    std::size_t boundary = 0;      // reference undecidable: exact touch, either answer right
    std::size_t wrong = 0;         // hit/miss differs from the reference (decided rays only)
    std::size_t false_hits = 0;    // ... of which the variant hit where the reference missed
    std::size_t within_rounding = 0;  // decided rays within float_band: any answer defensible
    std::size_t wrong_clear = 0;   // wrong on rays decided beyond float rounding: defects
    std::size_t t_scored = 0;      // rays where both hit: relative t error measured
    double t_median = 0.0, t_p99 = 0.0, t_max = 0.0;
    std::size_t self_hits = 0;     // surface families: re-hit the surface the ray left
    std::size_t leaks = 0;         // edges family: a ray from inside a closed shape escaped
    double seconds = 0.0;          // time spent in the variant on these rays, single thread
    double mrays_per_s() const { return seconds > 0.0 ? double(rays) / seconds * 1e-6 : 0.0; }
    double wrong_rate() const { return rays > boundary ? double(wrong) / double(rays - boundary) : 0.0; }
    double wrong_clear_rate() const {
        const std::size_t clear = rays - boundary - within_rounding;
        return clear ? double(wrong_clear) / double(clear) : 0.0;
    }
};

// A variant intersects a batch of (shape, ray) pairs and returns the seconds spent in the
// intersections alone (set-up such as building an Embree scene is not timed).
template <class Shape>
using Batch = std::function<double(const std::vector<Shape>& shapes, const std::vector<collision::Ray>& rays,
                                   std::vector<Result>& out)>;

// The faces of one closed surface (an icosphere, a cube of quads) against many rays: the nearest
// hit over all faces per ray.
template <class Face>
using MeshBatch = std::function<double(const std::vector<Face>& faces, const std::vector<collision::Ray>& rays,
                                       std::vector<Result>& out)>;

template <class Shape>
struct Variant {
    std::string name;
    Batch<Shape> batch;
    MeshBatch<Shape> mesh;  // used by the edges family of triangles and quads
};

// A variant given by a plain intersection function.
template <class Shape>
Variant<Shape> variant_of(std::string name, bool (*fn)(const collision::Ray&, const Shape&, collision::RayHit&));

// Every applicable family for one shape and its variants; `n` rays per family.
template <class Shape>
std::vector<Metrics> run_shape(const std::vector<Variant<Shape>>& variants, std::size_t n, std::uint64_t seed);

// One family for one variant (the Edges family of triangles and quads uses closed meshes).
template <class Shape>
Metrics run_family(const Variant<Shape>& variant, Family f, std::size_t n, std::uint64_t seed);

// Scores one family's results against the long-double reference (also `accuracy --score`,
// accuracy/exchange.cpp, for results computed outside the program).
template <class Shape>
Metrics score(const std::vector<Shape>& shapes, const std::vector<collision::Ray>& rays,
              const std::vector<Result>& results);

// Rays from inside closed meshes: every miss is a leak.
template <class Face>
Metrics run_closed_meshes(const Variant<Face>& variant, const std::vector<ClosedMeshCase<Face>>& meshes);

}  // namespace sweeptrace::accuracy

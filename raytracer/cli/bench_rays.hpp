#pragma once
// What both bench modes share: the rays (primary rays through the camera, plus one bounce from
// each primary hit), the shadow rays (from each primary hit, a segment to a point of a key light)
// and timed single-threaded passes of intersect() and occluded() over them.
//
// Ray rates are per second of the tracing thread's CPU time (wall time beside it): on a shared
// machine CPU time is the figure that does not depend on what else runs. Each timing is the
// median of `repeats` passes over the same rays, native's and Embree's passes alternating: a
// single pass of the shorter sets (tens of thousands of shadow rays, ~10 ms) swung by a few
// percent between runs, as much as the native / Embree margins it is read for, and a
// disturbance lasting several passes (seen: one that slowed five native passes in a row by 25%)
// then slows both sides, not one.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision/ray.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

double thread_cpu_seconds();
double wall_seconds();

struct BenchRays {
    std::vector<collision::Ray> rays;    // primary, then the bounce of each primary that hits
    std::vector<collision::Ray> shadow;  // one per primary hit: the segment to the key light
    // One per bounce hit: the segment to the key light (a render's next event estimation at the
    // path's second vertex; its own light samples, so `rays` and `shadow` stay as they were).
    std::vector<collision::Ray> shadow_bounce;
    // With a camera shutter: each ray's shutter fraction (a primary's, uniform in [0, 1), taken by
    // its bounce and shadow rays), parallel to the lists above; empty for a still scene.
    std::vector<float> ray_times, shadow_times, shadow_bounce_times;
};

// Primary rays through uniformly random film points, and from each primary hit (found with
// `accel`) one ray leaving it in a uniformly random direction of the normal's hemisphere, and
// one shadow ray: spawn_ray_to (as next event estimation makes them, ending short of the light)
// toward a uniformly random point of a square key light. The scene's own lights are not used
// (the framed meshes have none, the spheres field only a sky): the light is placed from the
// camera, above and to its right at its distance from look_at, facing look_at, its side a fifth
// of that distance, so the segments cross the scene the way a key light's shadow rays do.
BenchRays make_bench_rays(const Scene& scene, const Accel& accel, int primaries, std::uint64_t seed);

struct TraceResult {
    double cpu = 0.0, wall = 0.0;
    std::size_t hits = 0;
};

struct PairTimes {
    TraceResult native, embree;
};
// `times`, when not empty, holds each ray's shutter fraction (the queries with a time are timed).
PairTimes time_intersect(const Accel& native, const Accel& embree, const std::vector<collision::Ray>& rays, int repeats,
                         const std::vector<float>& times = {});
PairTimes time_occluded(const Accel& native, const Accel& embree, const std::vector<collision::Ray>& rays, int repeats,
                        const std::vector<float>& times = {});

// occluded() and intersect() over the same shadow rays, through the native structure and Embree.
struct ShadowTimes {
    TraceResult native_occluded, embree_occluded, native_intersect, embree_intersect;
};
ShadowTimes time_shadow(const Accel& native, const Accel& embree, const std::vector<collision::Ray>& rays, int repeats,
                        const std::vector<float>& times = {});

// The rays `accel` finds occluded, and the others (order kept in each).
struct SplitRays {
    std::vector<collision::Ray> blocked, unblocked;
};
SplitRays split_blocked(const Accel& accel, const std::vector<collision::Ray>& rays);

// An untimed pass over a slice of the rays, so no structure pays for first-touch page faults.
void warm_up(const Accel& accel, const BenchRays& bench);

}  // namespace sweeptrace

#pragma once
// The same scene through Embree 3: each mesh once as triangle geometry in a scene of its own,
// instanced (with the object's to_world) by every object that uses it; each analytic object as
// a one-primitive user geometry whose callbacks run geometry/intersect_object, so a hit means
// the same thing (error bound included) whichever structure found it.
// This header does not include Embree; only embree_accel.cpp does.
#include <memory>

#include "raytracer/accel/accel.hpp"

namespace sweeptrace {

struct EmbreeOptions {
    bool robust = false;    // RTC_SCENE_FLAG_ROBUST: Embree's watertight (slower) mode
    int build_threads = 0;  // 0: Embree's default (all cores); 1 for single-threaded timings
};

// Throws std::runtime_error when Embree reports an error while building.
std::unique_ptr<Accel> make_embree_accel(const Scene& scene, const EmbreeOptions& options = {});

}  // namespace sweeptrace

#pragma once
// `sweeptrace bench --meshes DIR [--rays N] [--repeat N]`: every .obj file of DIR (sorted by
// name) framed alone in a 320x320 film, the native BVH against Embree (default flags, one build
// thread) on the same rays (primary + one bounce for intersect(), a shadow ray per primary hit
// for occluded(), bench_rays.hpp), single-threaded. Per mesh it prints build time, SAH cost, bytes
// per triangle, Mrays/s of intersect() and occluded(), the native / Embree ratios, and
// occluded() against intersect() on the same shadow rays, each timing the median of --repeat
// passes. It prints figures; it asserts nothing.
#include <string>

namespace sweeptrace {

// Throws InputError when DIR is not a folder, holds no .obj file, or a mesh does not load.
void run_mesh_bench(const std::string& dir, int primaries, int repeats);

}  // namespace sweeptrace

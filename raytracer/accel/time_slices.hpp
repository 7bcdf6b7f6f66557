#pragma once
// How many equal slices of the shutter the native BVH gives a top level each (bvh_accel.hpp).
// One box over the whole shutter holds a fast object wherever it goes: a sphere moving 8 of its
// sizes has a box some 9 times longer, which every ray near its path enters. A top level per
// slice bounds each object only over its slice (motion_world_bounds over [k/K, (k+1)/K]); a ray
// takes the slice of its time. Embree's BVH4.MB splits time in its builder for the same reason;
// here the split is uniform and chosen once per scene. K is a power of two, so a ray's slice,
// floor(time K), is computed exactly and its time lies in the slice [k / K, (k + 1) / K] the
// slice's boxes were made for.
//
// The choice: a ray's chance to enter a box goes with its surface area (the SAH's model), so
// what slicing buys is the shrinking of the moving objects' boxes. For K in 1, 2, 4, 8, 16 the
// mean over moving primitives of their box area (averaged over the K slices) relative to the
// finest (K = 16) is computed; the smallest K within kSliceSlack of 1 is taken (more slices
// cost memory and build time, not traversal). A sum over all objects instead would be ruled by
// the largest still box (the spheres field's ground, a million times a small sphere's area),
// which no slicing changes. Measured in docs/motion-blur.md.
#include <vector>

#include "collision/bounds3.hpp"

namespace sweeptrace {

inline constexpr int kMaxTimeSlices = 16;
inline constexpr double kSliceSlack = 1.1;

// fine_boxes[i][k]: moving primitive i's box over slice k of kMaxTimeSlices. Returns K, a power
// of two in [1, kMaxTimeSlices] (1 for no moving primitive).
int choose_time_slices(const std::vector<std::vector<collision::Bounds3>>& fine_boxes);

}  // namespace sweeptrace

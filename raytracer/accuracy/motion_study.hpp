#pragma once
// Motion blur's hit/miss agreement (`sweeptrace accuracy --motion`): each kind of moving object
// alone in a scene, random rays at random shutter times aimed at the region it sweeps, traced
// by the native BVH and by Embree's motion blur and compared with brute force (every object in
// its pose at the ray's time, geometry/intersect_object.hpp), the reference both must match.
// The same table form as --structures: rays, and how many answers differ from the reference.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace sweeptrace::accuracy {

struct MotionRow {
    std::string motion;  // what moves, and how
    std::size_t rays = 0;
    std::size_t hits = 0;         // of brute force
    std::size_t bvh_differs = 0;  // hit/miss, or the t of a hit, differs from brute force's
    std::size_t embree_differs = 0;
    double embree_t_max = 0.0;  // largest relative t difference of Embree's hits where both hit
};

std::vector<MotionRow> measure_motion(std::size_t rays, std::uint64_t seed);

void write_motion_csv(std::ostream& out, const std::vector<MotionRow>& rows);
void write_motion_markdown(std::ostream& out, const std::vector<MotionRow>& rows);

}  // namespace sweeptrace::accuracy

// Capsule-capsule, discrete (thesis 3.1.5 "Fazole"). A Y-aligned capsule is the set of points
// within `radius` of its vertical core segment; two such capsules overlap (touching included)
// when the distance between their cores is <= r1 + r2. For parallel vertical segments that
// distance is exact in closed form: the horizontal offset and the vertical gap
// max(0, |y1 - y2| - (h1 + h2) / 2). The minimal translation is the exact one (push_out): along
// the offset between the nearest core points, by r1 + r2 minus their distance.
// Departures from the thesis, which tested the two end spheres and the cylinder side separately:
// one exact distance replaces the three tests (and their three answers); coaxial overlapping
// cores push along +X (the shortest way out, r1 + r2). Degenerate: radius <= 0, height < 0 or
// non-finite input gives hit = false (height 0 is a sphere). Computed in double.
#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {

Contact overlap(const Capsule& a, const Capsule& b) {
    using namespace detail;
    if (!valid_upright(a.center, a.radius, a.height) || !valid_upright(b.center, b.radius, b.height)) return {};
    const dvec3 d = to_double(a.center) - to_double(b.center);
    const double half = 0.5 * (double(a.height) + double(b.height));
    const double gap = std::abs(d.y) - half;
    const double gy = gap > 0.0 ? (d.y < 0.0 ? -gap : gap) : 0.0;
    return push_out(dvec3(d.x, gy, d.z), double(a.radius) + double(b.radius), dvec3(1, 0, 0));
}

}  // namespace collision

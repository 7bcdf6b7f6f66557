// Box-box, discrete (thesis 3.1.3): axis-aligned boxes overlap (touching included) when on
// every axis |c1 - c2| <= (s1 + s2) / 2. The minimal translation vector is along the axis of
// least overlap, signed to push the first box away from the second (exact for boxes: the
// Minkowski difference is a box and the nearest face wins). Ties between axes pick the lowest
// axis (x, then y, then z); equal centres on the chosen axis push toward +axis.
// Degenerate: a negative or non-finite size, or non-finite centre, gives hit = false; a zero
// size (a flat or point box) is a valid closed set.
// Decision in double: the half-sum and the centre difference are exact for float inputs of
// similar magnitude, so the comparison is exact up to one double rounding.
#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {

Contact overlap(const Aabb& a, const Aabb& b) {
    using namespace detail;
    if (!valid_box(a.center, a.size) || !valid_box(b.center, b.size)) return {};
    int best_axis = -1;
    double best_depth = 0.0, best_sign = 1.0;
    for (int i = 0; i < 3; ++i) {
        const double delta = double(a.center[i]) - double(b.center[i]);
        const double depth = 0.5 * (double(a.size[i]) + double(b.size[i])) - std::abs(delta);
        if (depth < 0.0) return {};
        if (best_axis < 0 || depth < best_depth) {
            best_axis = i;
            best_depth = depth;
            best_sign = delta < 0.0 ? -1.0 : 1.0;
        }
    }
    Contact c;
    c.hit = true;
    c.displacement[best_axis] = float(best_sign * best_depth);
    return c;
}

}  // namespace collision

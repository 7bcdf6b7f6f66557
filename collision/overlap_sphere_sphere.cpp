// Sphere-sphere, discrete (thesis 3.1.1). Overlap (touching included) when
// |c1 - c2| <= r1 + r2; the minimal translation of the first sphere is along c1 - c2 by
// r1 + r2 - |c1 - c2| (exact: the pair reduces to a point in a ball of radius r1 + r2).
// Departure from the thesis: coincident centres (normalize of a zero vector, NaN there) push the
// first sphere along +Y by r1 + r2; radius <= 0 or non-finite input gives hit = false.
// Decision and vector computed in double (detail/overlap_common.hpp): exact up to ~1e-16 relative.
#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {

Contact overlap(const Sphere& a, const Sphere& b) {
    using namespace detail;
    if (!valid_radius(a.radius) || !valid_radius(b.radius) || !finite(a.center) || !finite(b.center)) return {};
    return push_out(to_double(a.center) - to_double(b.center), double(a.radius) + double(b.radius), dvec3(0, 1, 0));
}

}  // namespace collision

// Ellipsoid-triangle, discrete (thesis 3.2.6): scale space about the ellipsoid's centre by
// 1 / radii so the ellipsoid becomes the unit sphere at the origin, run the sphere-triangle test
// on the scaled triangle, and scale the resulting vector back by the radii.
//
// Whether the two overlap is decided exactly (the scaling is an affine bijection, so it keeps
// overlap and touching). The scaled-back vector is NOT the ellipsoid's minimal translation
// vector in general (the thesis presents it as if it were): it is a translation that does
// separate the shapes (an affine map turns the unit sphere's separating translation v' into the
// ellipsoid's separating translation radii * v'), and its length is at most
// max(radii) / min(radii) times the true minimal one (the true MTV d maps to d / radii, which
// separates in scaled space, so |v'| <= |d| / min(radii)). For a sphere (equal radii) it is
// exact. tests/collision/test_overlap_round_triangle.cpp checks both properties.
// Degenerate: any radius <= 0, zero-area triangle or non-finite input gives hit = false.
#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {
Contact overlap(const Ellipsoid& e, const Triangle& tri) {
    using namespace detail;
    if (!valid_radius(e.radii.x) || !valid_radius(e.radii.y) || !valid_radius(e.radii.z)) return {};
    if (!finite(e.center) || !finite(tri.a) || !finite(tri.b) || !finite(tri.c)) return {};
    const dvec3 c = to_double(e.center), r = to_double(e.radii);
    Contact k = sphere_triangle(dvec3(0.0), 1.0, (to_double(tri.a) - c) / r, (to_double(tri.b) - c) / r,
                                (to_double(tri.c) - c) / r);
    if (k.hit) k.displacement = glm::vec3(dvec3(k.displacement) * r);
    return k;
}

}  // namespace collision

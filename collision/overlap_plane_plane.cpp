// Plane-plane (thesis 3.2.2, Ericson 5.4.4): the intersection line has direction u = n1 x n2
// and passes through p = ((n2 x u) d1 + (u x n1) d2) / (u . u), where d_i = n_i . point_i.
// Departure: the thesis (as OCR'd) writes (u x n2) d1 + (n1 x u) d2 without the division; the
// crosses there are in the opposite order, which yields -p, and the division by u . u is needed
// for non-perpendicular planes. The returned direction is unit length.
// Parallel or coincident planes (u . u == 0 in double: the cross product of float normals in
// double is exact up to one rounding per component, so this is an exact parallelism test for
// the given normals) and zero, non-finite or unrepresentable results return nullopt.
// Normals need not be unit length. Error: a few double roundings, then one float rounding; the
// point's error grows as 1 / sin(angle between the planes), as the geometry demands.
#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {

std::optional<Line> intersect(const Plane& a, const Plane& b) {
    using namespace detail;
    if (!finite(a.point) || !finite(a.normal) || !finite(b.point) || !finite(b.normal)) return std::nullopt;
    const dvec3 n1 = to_double(a.normal), n2 = to_double(b.normal);
    const dvec3 u = glm::cross(n1, n2);
    const double uu = glm::dot(u, u);
    if (!(uu > 0.0)) return std::nullopt;
    const double d1 = glm::dot(n1, to_double(a.point)), d2 = glm::dot(n2, to_double(b.point));
    const dvec3 p = (glm::cross(n2, u) * d1 + glm::cross(u, n1) * d2) / uu;
    const glm::vec3 pf(p), df(u / std::sqrt(uu));
    if (!finite(pf) || !finite(df)) return std::nullopt;
    return Line{pf, df};
}

}  // namespace collision

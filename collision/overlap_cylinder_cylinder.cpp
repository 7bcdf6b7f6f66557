// Cylinder-cylinder, discrete (thesis 3.1.3 "Válec a válec"): Y-aligned cylinders overlap
// (touching included) when their heights overlap, |y1 - y2| <= (h1 + h2) / 2, and their XZ
// circles overlap, (x1-x2)^2 + (z1-z2)^2 <= (r1 + r2)^2. The Minkowski difference of two
// Y-aligned cylinders is a Y-aligned cylinder (radius r1 + r2, height h1 + h2), so the minimal
// translation is exactly the smaller of the cap depth (along +-Y) and the side depth (along
// the horizontal centre offset), as the thesis does.
// Departures: coaxial cylinders (zero horizontal offset, where the thesis would normalise a
// zero vector) are pushed along +X; equal heights push toward +Y; ties prefer the cap.
// Degenerate: radius <= 0, height < 0 or non-finite input gives hit = false (height 0 is a
// disk, a valid closed set). Computed in double (detail/overlap_common.hpp).
#include "collision/overlap.hpp"
#include "collision/detail/overlap_common.hpp"

namespace collision {

Contact overlap(const Cylinder& a, const Cylinder& b) {
    using namespace detail;
    if (!valid_upright(a.center, a.radius, a.height) || !valid_upright(b.center, b.radius, b.height)) return {};
    const dvec3 d = to_double(a.center) - to_double(b.center);
    const double cap_depth = 0.5 * (double(a.height) + double(b.height)) - std::abs(d.y);
    if (cap_depth < 0.0) return {};
    const Contact side = push_out(dvec3(d.x, 0.0, d.z), double(a.radius) + double(b.radius), dvec3(1, 0, 0));
    if (!side.hit) return {};
    Contact c;
    c.hit = true;
    const double side_depth = glm::length(glm::dvec3(side.displacement));
    if (cap_depth <= side_depth)
        c.displacement.y = float(d.y < 0.0 ? -cap_depth : cap_depth);
    else
        c.displacement = side.displacement;
    return c;
}

}  // namespace collision

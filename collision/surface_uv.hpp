#pragma once
// Surface parameterisation of the curved shapes, computed only when asked: the ray tests of
// these shapes (intersect_sphere.cpp, ...) leave RayHit::uv at 0, because atan2 / acos on every
// hit cost a tenth of a sphere scene's render and nothing in the renderer reads it. Pass the
// RayHit the shape's intersect() returned (its point and normal, object space).
//
//   sphere:    (phi / 2 pi, theta / pi) of the normal, phi = atan2(n.z, n.x) in [0, 2 pi),
//              theta = acos(n.y): exactly what intersect() used to store.
//   ellipsoid: the same of n' = normalize((point - centre) / radii), the point mapped to the
//              unit sphere (intersect() used its own n' before re-projection: equal to a few
//              roundings).
//   cylinder:  side (phi / 2 pi around +y from +x toward +z, (y - ylo) / height); caps
//              ((x - cx) / 2r + 1/2, (z - cz) / 2r + 1/2). A cap hit is one whose normal has y != 0.
//   capsule:   (phi / 2 pi around +y from +x toward +z, (y - bottom) / (height + 2 r)).
//   oriented capsule: (angle around the axis from the basis vector t toward b of
//              detail::basis_around(axis), / 2 pi; (distance along the axis from a + r) /
//              (length + 2 r)); a zero-length axis is the sphere around a.
//   disk:      (rho / r, phi / 2 pi), polar coordinates around the centre on the basis (t, b)
//              of detail::basis_around(normal), from the float point (intersect() used the
//              double plane point: equal to a few roundings).
// Triangles, quads, boxes and planes still fill uv in intersect(): barycentrics and (s, t) are
// by-products of their tests, and the others cost a division.
// Degenerate input (a hit not from the shape's intersect()): whatever the formulas give.
#include <glm/vec2.hpp>

#include "collision/hit.hpp"
#include "collision/shapes.hpp"

namespace collision {

glm::vec2 surface_uv(const Sphere& s, const RayHit& hit);
glm::vec2 surface_uv(const Ellipsoid& e, const RayHit& hit);
glm::vec2 surface_uv(const Cylinder& c, const RayHit& hit);
glm::vec2 surface_uv(const Capsule& c, const RayHit& hit);
glm::vec2 surface_uv(const OrientedCapsule& c, const RayHit& hit);
glm::vec2 surface_uv(const Disk& d, const RayHit& hit);

}  // namespace collision

#pragma once
// Thesis-faithful discrete tests (collision::thesis), kept beside the robust defaults of
// collision/overlap.hpp as the "before" that tests and charts compare against. Only routines
// whose method differs from the default are here; each file says how.
//  - overlap(Sphere, Sphere): float, normalize(c1 - c2) -- NaN for coincident centres.
//  - overlap(Cylinder, Cylinder): strict comparisons (touching is not contact), float,
//    normalize of the XZ offset -- NaN for coaxial cylinders.
//  - overlap(Capsule, Capsule): the end spheres pairwise, then the cylinder sides; the first
//    test that hits gives the answer (its vector need not be the minimal one).
//  - overlap(Sphere, Triangle): centre projected on the plane, barycentrics by §2.4's formula;
//    inside -> plane distance; outside -> the edges in order, first hit wins.
//  - overlap(Triangle, Triangle): Möller in float with the thesis's sign test, which calls
//    coplanar triangles (all distances 0, "all on one side") apart.
// Mesh-level thesis variants are options of the defaults: SatAxes::faces and
// OctantRule::vertices (collision/mesh_mesh.hpp).
#include "collision/hit.hpp"
#include "collision/shapes.hpp"

namespace collision::thesis {

Contact overlap(const Sphere& a, const Sphere& b);
Contact overlap(const Cylinder& a, const Cylinder& b);
Contact overlap(const Capsule& a, const Capsule& b);
Contact overlap(const Sphere& s, const Triangle& tri);
bool overlap(const Triangle& a, const Triangle& b);

}  // namespace collision::thesis

// Thesis 3.1.1, 3.1.3 ("Válec a válec diskrétně") and 3.1.5 as written there: float arithmetic,
// no validation of the input, normalize() of whatever offset there is.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "collision/thesis/overlap.hpp"

namespace collision::thesis {

// Code 3.1.1.2: delta = pos1 - pos2; overlap when delta . delta <= (r1 + r2)^2;
// displacement = normalize(delta) * (r1 + r2 - |delta|). Coincident centres: NaN.
Contact overlap(const Sphere& a, const Sphere& b) {
    Contact res;
    const glm::vec3 delta = a.center - b.center;
    const float r = a.radius + b.radius;
    if (glm::dot(delta, delta) <= r * r) {
        res.hit = true;
        res.displacement = glm::normalize(delta) * (r - glm::length(delta));
    }
    return res;
}

// |y1 - y2| < h1/2 + h2/2 and (x1-x2)^2 + (z1-z2)^2 < (r1+r2)^2 (strict: touching is apart);
// the smaller of the cap depth and the side depth (r1 + r2) - |xz offset| resolves it, the side
// along normalize(xz offset) -- NaN for coaxial cylinders.
Contact overlap(const Cylinder& a, const Cylinder& b) {
    Contact res;
    const glm::vec3 d = a.center - b.center;
    const glm::vec2 xz(d.x, d.z);
    const float r = a.radius + b.radius;
    const float vertical = a.height / 2 + b.height / 2;
    if (!(std::abs(d.y) < vertical && glm::dot(xz, xz) < r * r)) return res;
    res.hit = true;
    const float depth_vertical = vertical - std::abs(d.y);
    const float depth_horizontal = r - glm::length(xz);
    if (depth_vertical < depth_horizontal) {
        res.displacement = glm::vec3(0, d.y < 0 ? -depth_vertical : depth_vertical, 0);
    } else {
        const glm::vec2 n = glm::normalize(xz) * depth_horizontal;
        res.displacement = glm::vec3(n.x, 0, n.y);
    }
    return res;
}

// "We check the individual spheres and then the cylinder sides; if one of the checks finds a
// collision we return its result": the four end-sphere pairs, then the cylinders of the core
// height. Detection is exact (the parts' union is the capsule, and a side-to-end contact
// always shows up as end-to-end or side-to-side); the vector is the first test's, not the
// minimal one, and a cylinder test can resolve along a flat cap that is not there.
Contact overlap(const Capsule& a, const Capsule& b) {
    const glm::vec3 up(0, 1, 0);
    const Sphere a_ends[2] = {{a.center + up * (a.height / 2), a.radius}, {a.center - up * (a.height / 2), a.radius}};
    const Sphere b_ends[2] = {{b.center + up * (b.height / 2), b.radius}, {b.center - up * (b.height / 2), b.radius}};
    for (const Sphere& sa : a_ends)
        for (const Sphere& sb : b_ends)
            if (Contact c = overlap(sa, sb); c.hit) return c;
    return overlap(Cylinder{a.center, a.radius, a.height}, Cylinder{b.center, b.radius, b.height});
}

}  // namespace collision::thesis

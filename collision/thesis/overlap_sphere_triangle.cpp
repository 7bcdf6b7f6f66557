// Thesis 3.2.4 as written there (after Ericson): project the centre on the triangle's plane,
// compute barycentrics with §2.4's formula (d00, d01, d11, d20, d21, denom); inside when all
// three are in [0, 1] -> contact when the plane distance |d| < r, vector along the plane
// normal by r - |d|. Otherwise the three edges in order (ab, bc, ca): the closest point with
// the parameter clamped (clamping makes the endpoint tests), contact when closer than r, the
// first edge that hits answers. Float; a zero-area triangle makes denom 0 and the barycentrics
// NaN (the inside test then fails and the edges decide).
#include <cmath>

#include <glm/geometric.hpp>

#include "collision/thesis/detail/barycentric.hpp"
#include "collision/thesis/overlap.hpp"

namespace collision::thesis {

Contact overlap(const Sphere& s, const Triangle& tri) {
    Contact res;
    const glm::vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
    const float d = glm::dot(s.center - tri.a, n);
    const glm::vec3 p = s.center - n * d;
    if (barycentric(tri, p).inside()) {
        if (std::abs(d) < s.radius) {
            res.hit = true;
            res.displacement = n * ((d < 0 ? -1.0f : 1.0f) * (s.radius - std::abs(d)));
        }
        return res;
    }
    const glm::vec3 ends[3][2] = {{tri.a, tri.b}, {tri.b, tri.c}, {tri.c, tri.a}};
    for (const auto& e : ends) {
        const glm::vec3 seg = e[1] - e[0];
        float t = glm::dot(s.center - e[0], seg) / glm::dot(seg, seg);
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        const glm::vec3 q = e[0] + seg * t;
        const float dist = glm::length(s.center - q);
        if (dist < s.radius) {
            res.hit = true;
            res.displacement = glm::normalize(s.center - q) * (s.radius - dist);
            return res;
        }
    }
    return res;
}

}  // namespace collision::thesis

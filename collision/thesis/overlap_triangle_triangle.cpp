// Thesis 3.2.3 as written there (Möller 1997 without its coplanar branch), in float:
// planes from the cross products of two edges, signed distances of the other triangle's
// vertices, rejection when the three signs are equal -- which includes three zeros, so
// coplanar triangles are always reported apart -- then the vertices projected on the
// intersection line's direction (p_i = D . V_i) and each triangle's interval from the two
// edges crossing the other plane, p0 + (p1 - p0) d0 / (d0 - d1). No epsilon: nearly coplanar
// triangles get signs from rounding noise.
#include <algorithm>

#include <glm/geometric.hpp>

#include "collision/thesis/overlap.hpp"

namespace collision::thesis {
namespace {

int sign(float x) { return (x > 0) - (x < 0); }

void interval(const float p[3], const float d[3], float& lo, float& hi) {
    int k;  // the vertex alone on its side (Möller's case analysis)
    if (d[0] * d[1] > 0) k = 2;
    else if (d[0] * d[2] > 0) k = 1;
    else if (d[1] * d[2] > 0 || d[0] != 0) k = 0;
    else if (d[1] != 0) k = 1;
    else k = 2;
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const float t1 = p[k] + (p[i] - p[k]) * d[k] / (d[k] - d[i]);
    const float t2 = p[k] + (p[j] - p[k]) * d[k] / (d[k] - d[j]);
    lo = std::min(t1, t2);
    hi = std::max(t1, t2);
}

}  // namespace

bool overlap(const Triangle& t0, const Triangle& t1) {
    const glm::vec3 v[3] = {t0.a, t0.b, t0.c}, u[3] = {t1.a, t1.b, t1.c};
    const glm::vec3 n0 = glm::cross(v[1] - v[0], v[2] - v[0]);
    const glm::vec3 n1 = glm::cross(u[1] - u[0], u[2] - u[0]);
    float du[3], dv[3];
    for (int i = 0; i < 3; ++i) {
        du[i] = glm::dot(n0, u[i]) - glm::dot(v[0], n0);
        dv[i] = glm::dot(n1, v[i]) - glm::dot(u[0], n1);
    }
    if (sign(du[0]) == sign(du[1]) && sign(du[1]) == sign(du[2])) return false;
    if (sign(dv[0]) == sign(dv[1]) && sign(dv[1]) == sign(dv[2])) return false;
    const glm::vec3 dir = glm::cross(n0, n1);
    const float pv[3] = {glm::dot(dir, v[0]), glm::dot(dir, v[1]), glm::dot(dir, v[2])};
    const float pu[3] = {glm::dot(dir, u[0]), glm::dot(dir, u[1]), glm::dot(dir, u[2])};
    float v_lo, v_hi, u_lo, u_hi;
    interval(pv, dv, v_lo, v_hi);
    interval(pu, du, u_lo, u_hi);
    return !(v_hi < u_lo || u_hi < v_lo);
}

}  // namespace collision::thesis

#pragma once
// Independent triangle-triangle reference for tests: the separating axis theorem in long double
// over the 17 candidate axes of two triangles (2 normals, 9 edge-edge crosses, 6 edge x normal
// for the coplanar case). Returns the largest separation gap over the axes, each axis
// normalised: > 0 means disjoint by that margin, <= 0 means overlapping (touching at 0).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "collision/shapes.hpp"

namespace testing {

inline long double tri_tri_gap(const collision::Triangle& ta, const collision::Triangle& tb) {
    using lvec = glm::tvec3<long double>;
    const lvec a[3] = {lvec(ta.a), lvec(ta.b), lvec(ta.c)}, b[3] = {lvec(tb.a), lvec(tb.b), lvec(tb.c)};
    const lvec ea[3] = {a[1] - a[0], a[2] - a[1], a[0] - a[2]}, eb[3] = {b[1] - b[0], b[2] - b[1], b[0] - b[2]};
    const lvec na = glm::cross(ea[0], ea[1]), nb = glm::cross(eb[0], eb[1]);
    lvec axes[17];
    int n = 0;
    axes[n++] = na;
    axes[n++] = nb;
    for (const lvec& x : ea)
        for (const lvec& y : eb) axes[n++] = glm::cross(x, y);
    for (const lvec& x : ea) axes[n++] = glm::cross(x, na);
    for (const lvec& y : eb) axes[n++] = glm::cross(y, nb);
    long double gap = -INFINITY;
    for (const lvec& ax : axes) {
        const long double len = std::sqrt(glm::dot(ax, ax));
        if (!(len > 1e-12L)) continue;
        const lvec u = ax / len;
        long double amin = INFINITY, amax = -INFINITY, bmin = INFINITY, bmax = -INFINITY;
        for (int i = 0; i < 3; ++i) {
            amin = std::min(amin, glm::dot(a[i], u));
            amax = std::max(amax, glm::dot(a[i], u));
            bmin = std::min(bmin, glm::dot(b[i], u));
            bmax = std::max(bmax, glm::dot(b[i], u));
        }
        gap = std::max({gap, bmin - amax, amin - bmax});
    }
    return gap;
}

}  // namespace testing

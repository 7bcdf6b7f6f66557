#pragma once
// Thesis §2.4 (from Ericson): barycentric coordinates of p with respect to a triangle, by the
// thesis's own formula. Shared by the thesis's segment-triangle and sphere-triangle variants.
// denom is 0 for a zero-area triangle; the division then gives inf/NaN, and inside() is false
// (NaN fails every comparison) — the thesis's behaviour, kept to be measured.
#include <glm/geometric.hpp>

#include "collision/shapes.hpp"

namespace collision::thesis {

struct Barycentric {
    float u = 0.0f, v = 0.0f, w = 0.0f;  // weights of a, b, c
    bool inside() const { return u >= 0.0f && u <= 1.0f && v >= 0.0f && v <= 1.0f && w >= 0.0f && w <= 1.0f; }
};

inline Barycentric barycentric(const Triangle& tri, const glm::vec3& p) {
    const glm::vec3 d0 = tri.b - tri.a, d1 = tri.c - tri.a, d2 = p - tri.a;
    const float d00 = glm::dot(d0, d0), d01 = glm::dot(d0, d1), d11 = glm::dot(d1, d1);
    const float d20 = glm::dot(d2, d0), d21 = glm::dot(d2, d1);
    const float denom = d00 * d11 - d01 * d01;
    Barycentric b;
    b.v = (d11 * d20 - d01 * d21) / denom;
    b.w = (d00 * d21 - d01 * d20) / denom;
    b.u = 1.0f - b.v - b.w;
    return b;
}

}  // namespace collision::thesis

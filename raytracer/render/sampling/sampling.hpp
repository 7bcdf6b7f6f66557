#pragma once
// Combining sampling strategies (MIS) and the colour measures the renderer's decisions use. The
// warps themselves live in geometry/warps.hpp.
#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

// Power heuristic (beta = 2) weight of a strategy with density `pdf_a` against one with `pdf_b`.
inline float power_heuristic(float pdf_a, float pdf_b) {
    const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    if (!std::isfinite(a)) return 1.0f;
    return a / (a + b);
}

inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
inline float max_component(const glm::vec3& c) { return std::max(c.r, std::max(c.g, c.b)); }

}  // namespace sweeptrace

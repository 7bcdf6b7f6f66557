#pragma once
// The pieces the curved shapes' uv parameterisations share (each home's uv() states its own):
// longitude and polar angle of a direction as fractions of a turn and a half-turn.
#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "raytracer/geometry/warps.hpp"

namespace sweeptrace::uv_maps {

// atan2(z, x) / 2 pi in [0, 1): 0 toward +X, 1/4 toward +Z.
inline float longitude(float x, float z) {
    const float a = std::atan2(z, x) / (2.0f * kPi);
    return a < 0.0f ? a + 1.0f : a;
}

// acos(y) / pi of a unit direction: 0 at +Y, 1 at -Y.
inline float polar(float y) { return std::acos(std::clamp(y, -1.0f, 1.0f)) / kPi; }

}  // namespace sweeptrace::uv_maps

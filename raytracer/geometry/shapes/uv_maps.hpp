#pragma once
// The pieces the curved shapes' uv parameterisations share (each home's uv() states its own):
// longitude and polar angle of a direction as fractions of a turn and a half-turn.
#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

// The derivatives of a surface point by its uv parameters, in object space, at one point
// (tangent_frame in render/materials/shading_frame.hpp builds a normal map's frame from them). Zero where
// the parameterisation is degenerate (a pole, a cap's centre): no normal map applies there.
struct UvTangents {
    glm::vec3 dpdu{0.0f}, dpdv{0.0f};
};

}  // namespace sweeptrace

namespace sweeptrace::uv_maps {

// atan2(z, x) / 2 pi in [0, 1): 0 toward +X, 1/4 toward +Z.
inline float longitude(float x, float z) {
    const float a = std::atan2(z, x) / (2.0f * kPi);
    return a < 0.0f ? a + 1.0f : a;
}

// acos(y) / pi of a unit direction: 0 at +Y, 1 at -Y.
inline float polar(float y) { return std::acos(std::clamp(y, -1.0f, 1.0f)) / kPi; }

// d(point)/du of the longitude map at offset d from the axis (Y): 2 pi (-d.z, 0, d.x); zero on
// the axis itself.
inline glm::vec3 longitude_tangent(const glm::vec3& d) { return 2.0f * kPi * glm::vec3(-d.z, 0.0f, d.x); }

// d(point)/dv of the sphere map (polar angle / pi) at offset d from the centre: pi times the
// meridian tangent toward -Y, of length |d|; zero at the poles.
inline glm::vec3 polar_tangent(const glm::vec3& d) {
    const float rho = std::sqrt(d.x * d.x + d.z * d.z);
    if (!(rho > 0.0f)) return glm::vec3(0.0f);
    return kPi * glm::vec3(d.y * d.x / rho, -rho, d.y * d.z / rho);
}

}  // namespace sweeptrace::uv_maps

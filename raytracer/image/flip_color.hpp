#pragma once
// The colour spaces FLIP works in (Andersson et al. 2020, section 3; formulas in docs/flip.md).
// All in double. Linear RGB is sRGB primaries with the D65 white at the CIE five-digit
// chromaticity (0.31271, 0.32902); the RGB -> XYZ matrix is derived from those chromaticities
// (not typed in), and the reference white (Xn, Yn, Zn) is the XYZ of linear RGB (1, 1, 1), so
// white maps to L* = 100, a* = b* = 0 exactly.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace::flip_color {

const glm::dmat3& rgb_to_xyz_matrix();
const glm::dmat3& xyz_to_rgb_matrix();
glm::dvec3 reference_white();  // XYZ of linear RGB (1, 1, 1)

glm::dvec3 linear_rgb_to_xyz(const glm::dvec3& rgb);
glm::dvec3 xyz_to_linear_rgb(const glm::dvec3& xyz);

// Opponent space of Zhang & Wandell: Yy = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn).
glm::dvec3 xyz_to_ycxcz(const glm::dvec3& xyz);
glm::dvec3 ycxcz_to_xyz(const glm::dvec3& ycxcz);

// CIELAB relative to reference_white() (CIE 15 piecewise cube root).
glm::dvec3 xyz_to_lab(const glm::dvec3& xyz);

// The Hunt effect as FLIP models it: a* and b* scaled by 0.01 L* (dark colours look less saturated).
glm::dvec3 hunt_adjust(const glm::dvec3& lab);

// HyAB distance (Abasi et al. 2020): |L1 - L2| + sqrt((a1 - a2)^2 + (b1 - b2)^2).
double hyab(const glm::dvec3& lab1, const glm::dvec3& lab2);

}  // namespace sweeptrace::flip_color

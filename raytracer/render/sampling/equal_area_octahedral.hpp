#pragma once
// The equal-area octahedral map between the unit square and the unit sphere: Clarberg, "Fast
// Equal-Area Mapping of the (Hemi)Sphere using SIMD" (JGT 2008), in the layout pbrt-v4's
// EqualAreaSquareToSphere / EqualAreaSphereToSquare use for its ImageInfiniteLight, so a pbrt-v4
// environment image reads here texel for texel. Frame: pbrt's, +z at the square's centre, -z at
// its four corners, +x toward u = 1 and +y toward v = 1 (both at the middle of those edges).
//
// Derivation (per quadrant; signs of (u, v) in [-1, 1]^2 give the signs of x and y). Let
// a = |u|, b = |v|. The inner diamond a + b <= 1 is the upper hemisphere: r = a + b, and the
// diamond of radius r (area 2 r^2 of the square's 4) maps to the cap z >= 1 - r^2 (area
// 2 pi r^2 of the sphere's 4 pi), the same fraction, so the map is equal-area in r; along the
// segment a + b = r the azimuth phi = (pi / 4) ((b - a) / r + 1) runs linearly over [0, pi / 2],
// equal-area in phi. The outer triangles a + b > 1 fold onto the lower hemisphere with
// r = 2 - (a + b), z = -(1 - r^2). In both, sin(theta) = r sqrt(2 - r^2), so the result has unit
// length exactly in real arithmetic. A square of area A anywhere maps to a solid angle of pi A
// (u, v in [0, 1]: 4 pi A), which is why a texel's solid angle is 4 pi / (W H) for every texel.
//
// Departures from pbrt-v4: std::cos, std::sin and std::atan2 where pbrt uses polynomial fits
// (its atan fit is off by up to 4.1e-6 in atan x 2 / pi, so its u, v by up to 2e-6: a hundredth
// of a texel of a 4096 map, a lookup differs only that close to a texel's edge), and
// r = sqrt((x^2 + y^2) / (|d| (|d| + |z|))), the same as pbrt's sqrt(1 - |z|) for a unit vector,
// which keeps r's digits near the poles (where 1 - |z| cancels) and takes a direction of any
// length. Round trip square -> sphere -> square is within 5e-7 in u and v (measured 1.2e-7, one
// float ulp of 1; tests/raytracer/test_render_environment_equal_area.cpp holds it to that).
//
// The square's edges are folded: (0, v) and (0, 1 - v) are one direction, as are (u, 0) and
// (1 - u, 0), and the four corners are all -z.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace {

// p in [0, 1]^2 -> a unit direction (pbrt's light space, z up).
glm::vec3 equal_area_square_to_sphere(const glm::vec2& p);
// A non-zero direction (any length) -> its point of [0, 1]^2.
glm::vec2 equal_area_sphere_to_square(const glm::vec3& d);

}  // namespace sweeptrace

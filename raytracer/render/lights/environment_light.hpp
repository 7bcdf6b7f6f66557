#pragma once
// An environment map as a light: radiance by direction, and importance sampling of directions by
// a 2D piecewise-constant distribution over the texels (pbrt-v4's ImageInfiniteLight, without
// its MIS compensation). Two image layouts (Background::mapping), one map frame.
//
// Map frame. A world direction d is first turned into the map's frame by the inverse of the
// background's turn R (a right-handed rotation about +Y by rotate_degrees, like a transform's
// rotate about [0, 1, 0], or any rotation `turn` given as an axis and degrees), then, when
// mirrored, reflected by S = diag(-1, 1, 1) (x negated after the turn): d' = S R^-1 d, and back
// d = R S d'. S is not a rotation: it is what pbrt-v3's equirect convention, the mirror image of
// ours, needs. Both layouts read (u, v)
// in [0, 1]^2 with u along the columns left to right and v along the rows top to bottom (row 0 the
// file's first), texel (floor(u W), floor(v H)) clamped to the image; radiance is that texel's
// value (nearest, piecewise constant) times scale.
//
// Equirect (the default). theta = acos(d'.y) in [0, pi] (0 = +Y, the top row) and
// phi = atan2(d'.x, -d'.z) in (-pi, pi], u = 1/2 + phi / (2 pi), v = theta / pi: the image's
// centre looks along -Z, its right half toward +X (mirrored: toward -X, the image read right to
// left, u -> 1 - u). d omega = 2 pi^2 sin(theta) du dv.
//
// Equal-area (pbrt-v4's layout, a square image). w = (d'.x, -d'.z, d'.y) is pbrt's z-up light
// space (a proper rotation: pbrt's `Rotate -90 1 0 0` that turns a z-up map to our y-up; a
// pbrt-v4 scene that rotates its map that way gets rotate 0 here), and (u, v) =
// equal_area_sphere_to_square(w) (render/sampling/equal_area_octahedral.hpp, Clarberg 2008): the image's
// centre is +Y, its four corners -Y, the diamond through its edges' midpoints the horizon; the
// middle of its right edge, (1, 1/2), is +X, of its top edge, (1/2, 0), +Z (mirrored: the right
// edge's middle is -X). d omega = 4 pi du dv everywhere.
//
// Sampling. Texel (i, j) gets weight luminance(texel) J_j with the row's Jacobian factor
// J_j = sin(theta_j) (equirect, theta_j at the row's centre) or 1 (equal-area); a row is chosen by
// the marginal of the row sums, a column by that row's conditional, each with a uniform offset
// inside the cell, so the density on the unit square is p(u, v) = w_ij / mean(w), and on the sphere
//   equirect:   p(omega) = p(u, v) / (2 pi^2 sin(theta)), theta the direction's own polar angle,
//   equal-area: p(omega) = p(u, v) / (4 pi).
// pdf() evaluates exactly this for any direction, so the density used in MIS is the one sampled
// with; an equal-area sample reports pdf() and the radiance of the texel its direction maps back
// to, the same numbers a BSDF-sampled ray along it gets. Texels of weight 0 are never sampled and
// have pdf 0; their radiance is 0 too (RGB is non-negative and every luminance coefficient is
// positive), so nothing is missed.
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// The texel (column, row) a world direction reads and the direction in the map's frame: the one
// lookup radiance and density share.
struct EnvironmentLookup {
    glm::vec3 local{0.0f};
    int col = 0, row = 0;
};
EnvironmentLookup look_up_environment(const Background& bg, const glm::vec3& dir);

// Radiance of an Environment background along unit direction `dir` (scale included).
glm::vec3 environment_radiance(const Background& bg, const glm::vec3& dir);

class EnvironmentLight {
public:
    explicit EnvironmentLight(const Background& bg);

    bool emits() const { return total_ > 0.0; }
    // The integral of luminance over the sphere, int lum(L) d omega (scale included).
    double luminance_integral() const { return integral_; }
    // The largest irradiance (luminance) the map gives a small disc, over the disc's orientations
    // n: max_n int lum(L) max(0, n . omega) d omega. What a sun's E is for the sun (the disc facing
    // it), so light selection can weigh the two alike (lights.hpp). From the map's order-2
    // spherical harmonics (Ramamoorthi and Hanrahan 2001: within a few percent of the exact
    // irradiance; a single bright texel gives 1.06 x its lum d omega, a uniform map pi L exactly),
    // maximised over 256 orientations. A uniform sky gives a quarter of luminance_integral().
    double max_irradiance() const { return max_irradiance_; }

    glm::vec3 radiance(const glm::vec3& dir) const { return environment_radiance(*bg_, dir); }
    // A direction from two uniforms in [0, 1), its solid-angle density and radiance; false for a
    // degenerate sample (equirect at a pole, where sin(theta) = 0) or one of density 0.
    bool sample(float u1, float u2, glm::vec3& dir, float& pdf, glm::vec3& radiance) const;
    float pdf(const glm::vec3& dir) const;

private:
    // The solid-angle density at a looked-up direction (pdf() of it).
    float density(const EnvironmentLookup& l) const;
    // One piecewise-constant 1D distribution: bins of width 1/n with weights f.
    struct Distribution1D {
        std::vector<float> f;
        std::vector<float> cdf;  // n + 1 entries, cdf[0] = 0, cdf[n] = 1
        double sum = 0.0;
        void build(std::vector<float> weights);
        // The continuous sample in [0, 1) and its bin; the density there is f[bin] / mean(f).
        float sample(float u, int& bin) const;
        float density(int bin) const { return static_cast<float>(f[static_cast<std::size_t>(bin)] * f.size() / sum); }
    };

    const Background* bg_;
    int width_ = 0, height_ = 0;
    std::vector<Distribution1D> rows_;  // conditional per row (columns)
    Distribution1D marginal_;           // over rows
    double total_ = 0.0;                // sum of all weights
    double integral_ = 0.0;
    double max_irradiance_ = 0.0;
};

}  // namespace sweeptrace

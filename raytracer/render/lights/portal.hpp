#pragma once
// A portal: the rectangle (a window) through which an infinite light reaches the scene's
// inside, so next event estimation draws directions only inside the solid angle it subtends
// (Bitterli, Novak and Jarosz 2015, "Portal-Masked Environment Map Sampling"; pbrt-v4's
// `portal`). Here the directions are uniform in that solid angle, by Urena, Fajardo and King's
// spherical-rectangle sampling (2013): the density is exactly 1 / Omega(p) for every direction
// whose ray from p crosses the rectangle, and 0 for every other direction. pdf() decides
// "crosses" by intersecting the ray with the rectangle and rebuilds the same Omega(p), so it
// returns the density sample() drew with.
//
// A portal changes a light's sampling, never its radiance: light that reaches the scene by any
// other way (a second window, a point outside the room) is still found by BSDF-sampled rays,
// with MIS weight 1 there because the portal's density is 0, so a render stays unbiased
// whatever the portal covers; it is only noisier where the portal misses light.
//
// The rectangle's corners c0, c1, c2, c3 go round its edge (pbrt-v4's order); either side may
// face the scene (a point sees the same solid angle from both sides). The scene loader checks
// that they are a rectangle (scene/load_scene.cpp); here c0, c1 and c3 span it.
#include <array>

#include <glm/vec3.hpp>

namespace sweeptrace {

class Portal {
public:
    explicit Portal(const std::array<glm::vec3, 4>& corners);

    // A unit direction from p through the rectangle, uniform in its solid angle, from two
    // uniforms in [0, 1), and that density; false when p lies in the rectangle's plane.
    bool sample(const glm::vec3& p, float u1, float u2, glm::vec3& dir, float& pdf) const;
    // The density sample(p, ...) gives unit direction dir: 1 / Omega(p) if the ray from p along
    // dir crosses the rectangle, else 0.
    float pdf(const glm::vec3& p, const glm::vec3& dir) const;
    // The solid angle the rectangle subtends at p (0 in its plane).
    double solid_angle(const glm::vec3& p) const;

private:
    struct View;  // the rectangle in p's frame (portal.cpp)
    bool view_from(const glm::vec3& p, View& v) const;

    glm::dvec3 corner_{0.0};       // c0
    glm::dvec3 ex_{0.0}, ey_{0.0}; // unit edge directions c0 -> c1, c0 -> c3
    glm::dvec3 ez_{0.0};           // unit normal ex x ey
    double width_ = 0.0, height_ = 0.0;
};

}  // namespace sweeptrace

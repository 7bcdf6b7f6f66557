#pragma once
// Next event estimation of a sky without a portal, guided by what it learned. A uniform colour or
// the horizon-to-zenith sky with no portal is no light for next event estimation in general
// (drawn uniformly over the sphere it finds a window no more often than cosine-weighted BSDF
// sampling does, and costs a shadow ray: docs/sky-and-portals.md). Where path guiding runs, it
// also learns where the sky's light comes from, from the sky's MIS-weighted estimates L cos /
// density (next event samples of the sky, and BSDF-sampled rays that escaped to it, so that the
// first pass, which has no sky samples, teaches it too), two ways:
// - per guiding leaf, the directions over the sphere in which the sky is seen from the leaf's
//   region (a DirectionalQuadtree, as the path guide's): where a leaf learned nothing, the sky is
//   not sampled there;
// - for the whole scene, where on the box around the guide's first records the rays that reach
//   the sky leave it (SkyExitGuide): a learned portal. An opening is the same place seen from
//   every point, so this part keeps its aim across a leaf's region, where the leaf's directions
//   (learned from all its points) blur by the parallax of the leaf's size.
// At a vertex whose leaf learned the sky, the sky is one more light for next event estimation
// (LightSet::sample with the guide), its direction drawn from a defensive one-sample mixture:
// uniform over the sphere (kSkyUniformFraction), the leaf's directions, and the learned exits
// (the last two sharing the rest, sky_guide.cpp's kLeafShare; the exits only for points inside
// their box, the leaf's directions taking their share elsewhere). Its
// density, the mixture's, is what next event estimation divides by and what the MIS weight of an
// escaped BSDF-sampled ray from that vertex uses (LightSet::pdf, LightSet::guided_sky_weight):
// the strategies at a vertex are a choice made from where the vertex lies and what was learned
// before the pass, so any such rule keeps the estimator unbiased as long as both sides of MIS
// read the same guide. The uniform part keeps a non-zero density wherever the sky shines,
// whatever the guide missed. Where nothing was learned (the first pass, guiding off, bdpt and
// vcm) the sky stays BSDF sampling's alone, as before.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raytracer/render/guiding/guiding_quadtree.hpp"

namespace sweeptrace {

// The uniform part's share. Measured on scenes/sky-window.json without its portal (160 spp,
// seeds 7 and 8, RMSE): 0.1 gave 0.93x 0.25's, 0.5 1.19x.
inline constexpr float kSkyUniformFraction = 0.1f;

// Where rays that reach the sky leave a box: a distribution over the box's six faces, learned on
// a quadtree over the square whose 4 x 2 slots hold the faces (face 2a is the low side of axis a,
// 2a + 1 the high; slots 6 and 7 stay empty), and the solid-angle density it gives a direction
// from a point inside the box: the ray from the point meets the box's surface once, so a
// direction and an exit point are one to one, p_omega = p_area d^2 / |cos| at the exit.
class SkyExitGuide {
public:
    // The box (the first pass's records, so every shading point then seen lies inside), and the
    // structure the first records go into (zero energy).
    void start(const glm::vec3& lo, const glm::vec3& hi, const DirectionalQuadtree& structure);
    bool has_box() const { return has_box_; }
    // Strictly inside the box: the exit map is defined.
    bool covers(const glm::vec3& p) const;

    // Adds `value` at the exit of the ray from p along unit `dir` (p inside the box).
    void record(const glm::vec3& p, const glm::vec3& dir, float value);
    double total() const { return tree_.total(); }
    void freeze() { tree_.freeze(); }
    // Zero energy, the structure this one's energy asks for (DirectionalQuadtree::refined).
    SkyExitGuide refined(double threshold, int max_depth) const;

    // Requires covers(p), total() > 0 and freeze(). The solid-angle density of the direction,
    // and a unit direction drawn from it (false when the draw degenerates).
    float pdf(const glm::vec3& p, const glm::vec3& dir) const;
    bool sample(const glm::vec3& p, float u1, float u2, glm::vec3& dir) const;
    void prefetch() const { tree_.prefetch(); }

private:
    // The exit of the ray from p along dir: its point on the square, and p_area / p_square times
    // d^2 / |cos| there (the factor that takes the square's density to the direction's).
    bool exit_square(const glm::vec3& p, const glm::vec3& dir, glm::vec2& square, float& to_solid_angle) const;

    DirectionalQuadtree tree_;
    glm::vec3 lo_{0.0f}, hi_{0.0f};
    bool has_box_ = false;
};

// What a vertex's next event estimation of the sky reads: its leaf's learned directions (always
// set when there is a guide at all) and the scene's learned exits (nullptr when none yet).
struct SkyGuide {
    const DirectionalQuadtree* leaf = nullptr;
    const SkyExitGuide* exit = nullptr;
};

// The mixture's solid-angle density of unit direction `dir` from `p`.
float sky_mixture_density(const SkyGuide& guide, const glm::vec3& p, const glm::vec3& dir);

// A unit direction toward the sky from the mixture, from two uniforms (u.x picks the branch and
// is stretched back over [0, 1) inside it, so no sampler dimension is added), and its density;
// false when the draw degenerates (density 0).
bool sample_sky_mixture(const SkyGuide& guide, const glm::vec3& p, glm::vec2 u, glm::vec3& dir, float& density);

}  // namespace sweeptrace

#pragma once
// The multiple importance sampling weights of the bidirectional methods, power heuristic, from
// the densities of the whole path: bdpt's connection strategies (Veach 1997, §10.2) and, when a
// merging density eta > 0 is given, vcm's merges in the same sums (Georgiev, Křivánek, Davidovič,
// Slusallek 2012, §5). The one home of both: bdpt.cpp and vcm.cpp fill a MisPath from their
// subpaths by gather_mis_path and ask mis_weight; neither builds the arrays itself.
//
// Connections. A path x_0 ... x_k runs from the light (x_0) to the camera (x_k). Strategy s takes
// x_0..x_{s-1} from a light subpath and x_s..x_k from the camera subpath (t = k + 1 - s camera
// vertices) and connects x_{s-1} to x_s. Its density is
//   p_s = A_s * prod_{1 <= i < s} from_light[i] * prod_{i >= s} from_camera[i],
// from_light[i] the density of x_i sampled from x_{i-1}, from_camera[i] from x_{i+1}, and A_s how
// x_0 itself was drawn: nothing (from_camera[0] already counts it, s = 0), next event estimation's
// density nee0 (s = 1, when t >= 2: the light point is drawn by LightSet::sample from x_1, the cone
// for a sphere), or emission sampling's from_light[0] (s >= 2, and s = 1 with t = 1, where the
// light subpath's own point is connected to the camera). So the density used for every strategy is
// the one it samples with. The ratios p_{i+1} / p_i are nee0 / from_camera[0] (i = 0),
// from_light[0] from_light[1] / (nee0 from_camera[1]) (i = 1) and from_light[i] / from_camera[i]
// beyond. Impossible strategies: s = 0 when the light cannot be hit (points, spots, delta
// directions); t = 0 (the lens is never hit); any connection at a vertex that scattered by a delta
// lobe; s = 1, t = 1 from a light at infinity. Densities of 0 (delta lobes) count as 1, as pbrt
// does: they appear only next to an impossible strategy, where they cancel.
//
// Merges. Merging at x_s (1 <= s <= k - 1) takes x_0..x_s from a light subpath and x_s..x_k from
// the camera subpath, and accepts the pair when the light subpath's x_s lies within r of the
// camera's. Its density is connection strategy s's times the light subpath's density of reaching
// x_s and the chance of landing within r: p_VM(s) = p_VC(s) * from_light[s] * eta, eta = pi r^2 N,
// N the light subpaths each camera subpath merges with. For s = 1 the light point x_0 is emission
// sampling's (from_light[0]), not next event estimation's (nee0), so the connection density's nee0
// is traded for from_light[0]. A merge needs a non-delta x_s only: it is how light reaches a
// diffuse surface through a specular one (x_{s-1} delta), which no connection can.
//
// The weight is p^2 / sum over the possible techniques of p_i^2. Russian roulette is left out of
// the densities (as pbrt-v3): any weights that sum to 1 over the techniques of each path keep the
// estimator unbiased; test_render_bdpt.cpp and test_render_vcm.cpp check the sums.
#include <span>
#include <vector>

#include "raytracer/render/integrators/path_vertex.hpp"
#include "raytracer/render/lights.hpp"

namespace sweeptrace {

struct MisPath {
    int k = 0;                       // x_0 .. x_k, x_k the camera
    std::vector<float> from_light;   // k + 1 entries: x_i's density sampled from x_{i-1}
    std::vector<float> from_camera;  // x_i's density sampled from x_{i+1}
    std::vector<char> delta;         // x_i scattered by a delta lobe (never set at the connection's ends)
    float nee0 = 0.0f;               // next event estimation's density of x_0 from x_1 (used when k >= 2)
    bool light_hittable = true;      // strategy s = 0 exists
    bool light_to_camera = true;     // strategy s = 1 exists when k = 1
};

// Defects planted for the mutation tests (render/planted_defect.hpp): next event estimation (s = 1)
// left out of the sums, so the weights no longer sum to 1; or the merges left out of the
// connections' sums (bdpt's weights under merging), so they sum to more than 1.
enum class MisDefect { None, DropNee, DropMerges };

// The weight of connection strategy s (merge = false) or of merging at x_s (merge = true), over the
// connections and, with eta > 0, the merges. With eta = 0 there are no merges: bdpt's weights.
float mis_weight(const MisPath& path, int s, bool merge, float eta, MisDefect defect = MisDefect::None);

// The densities of the path x_0..x_k as its subpaths sampled them, in light-to-camera order: x_i =
// light[i] for i < light.size(), x_i = cam[k - i] for k - i < cam.size(); entries neither covers
// are 0, and the connection's (or merge's) own entries are the caller's to set. With a light
// vertex, nee0 and the strategies it allows come from light[0] (`lights` says whether a light at
// infinity is found by escaping rays).
void gather_mis_path(MisPath& m, int k, std::span<const PathVertex> light, std::span<const PathVertex> cam,
                     const LightSet& lights);

}  // namespace sweeptrace

#pragma once
// The multiple importance sampling weight of one technique of vertex connection and merging
// (Georgiev, Křivánek, Davidovič, Slusallek 2012, §5), by the power heuristic over bdpt's
// connection strategies and the merges, from the densities of the whole path (bdpt_mis.hpp's
// MisPath, read the same way).
//
// Merging at x_s (1 <= s <= k - 1) takes x_0..x_s from a light subpath and x_s..x_k from the
// camera subpath, and accepts the pair when the light subpath's x_s lies within r of the camera's.
// Its density is the connection strategy s's times the light subpath's density of reaching x_s and
// the chance of landing within r: p_VM(s) = p_VC(s) * fwd[s] * eta, eta = pi r^2 N, N the light
// subpaths each camera subpath merges with (all of the iteration's, one per pixel). For s = 1 the
// light point x_0 is emission sampling's (fwd[0]), not next event estimation's (nee0), so the
// connection density's nee0 is traded for fwd[0]. A merge needs a non-delta x_s only: it is how
// light reaches a diffuse surface through a specular one (x_{s-1} delta), which no connection can.
// With eta = 0 there are no merges and the weights are bdpt_mis_weight's.
#include "raytracer/render/integrators/bdpt_mis.hpp"

namespace sweeptrace {

// The weight of connection strategy s (merge = false) or of merging at x_s (merge = true).
// `drop_merges` plants a defect for the mutation tests: the merges left out of the sums of the
// connection strategies' weights (bdpt's weights under merging), so the weights sum to more than 1.
float vcm_mis_weight(const MisPath& path, int s, bool merge, float eta, bool drop_merges = false);

}  // namespace sweeptrace

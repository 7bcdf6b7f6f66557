#pragma once
// The multiple importance sampling weight of one bidirectional strategy (power heuristic,
// Veach 1997 §10.2), from the densities of the whole path, without rebuilding it per strategy.
//
// A path x_0 ... x_k runs from the light (x_0) to the camera (x_k). Strategy s takes x_0..x_{s-1}
// from a light subpath and x_s..x_k from the camera subpath (t = k + 1 - s camera vertices) and
// connects x_{s-1} to x_s. Its density is
//   p_s = A_s * prod_{1 <= i < s} fwd[i] * prod_{i >= s} rev[i],
// fwd[i] the density of x_i sampled from x_{i-1}, rev[i] from x_{i+1}, and A_s how x_0 itself was
// drawn: nothing (rev[0] already counts it, s = 0), next event estimation's density nee0 (s = 1,
// when t >= 2: the light point is drawn by LightSet::sample from x_1, the cone for a sphere), or
// emission sampling's fwd[0] (s >= 2, and s = 1 with t = 1, where the light subpath's own point is
// connected to the camera). So the density used for every strategy is the one it samples with.
// The ratios p_{i+1} / p_i are nee0 / rev[0] (i = 0), fwd[0] fwd[1] / (nee0 rev[1]) (i = 1) and
// fwd[i] / rev[i] beyond; the weight is p_s^2 / sum p_i^2 over the possible strategies i.
// Impossible strategies: s = 0 when the light cannot be hit (points, spots, delta directions);
// t = 0 (the lens is never hit); any connection at a vertex that scattered by a delta lobe; s = 1,
// t = 1 from a light at infinity. Densities of 0 (delta lobes) count as 1, as pbrt does: they
// appear only next to an impossible strategy, where they cancel.
// Russian roulette is left out of the densities (as pbrt-v3): any weights that sum to 1 over the
// strategies of each path keep the estimator unbiased; test_render_bdpt_mis.cpp checks the sum.
#include <vector>

namespace sweeptrace {

struct MisPath {
    int k = 0;                 // x_0 .. x_k, x_k the camera
    std::vector<float> fwd;    // k + 1 entries
    std::vector<float> rev;
    std::vector<char> delta;   // x_i scattered by a delta lobe (never set at the connection's ends)
    float nee0 = 0.0f;         // next event estimation's density of x_0 from x_1 (used when k >= 2)
    bool light_hittable = true;       // strategy s = 0 exists
    bool light_to_camera = true;      // strategy s = 1 exists when k = 1
};

// The power-heuristic weight of strategy s of `path`. `drop_nee` plants a defect for the mutation
// tests: the next event strategy (s = 1) left out of the sum, so the weights no longer sum to 1.
float bdpt_mis_weight(const MisPath& path, int s, bool drop_nee = false);

// The two steps of that weight, for vcm_mis.cpp, which adds merging to the same sums: whether
// strategy i exists for `path`, and p_{i+1} / p_i (delta densities counted as 1), 0 <= i < k.
bool bdpt_strategy_possible(const MisPath& path, int i);
float bdpt_density_ratio(const MisPath& path, int i);

}  // namespace sweeptrace

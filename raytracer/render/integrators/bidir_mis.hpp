#pragma once
// The multiple importance sampling weights of the bidirectional methods, power heuristic, from
// the densities of the path: bdpt's connection strategies (Veach 1997, §10.2) and, when a merging
// density eta > 0 is given, vcm's merges in the same sums (Georgiev, Křivánek, Davidovič,
// Slusallek 2012, §5). The one home of both: bdpt.cpp and vcm.cpp fill a MisPath around the
// connection or merge (mis_window.hpp) and ask mis_weight; neither sums the strategies itself.
//
// Connections. A path x_0 ... x_k runs from the light (x_0) to the camera (x_k). Strategy s takes
// x_0..x_{s-1} from a light subpath and x_s..x_k from the camera subpath (t = k + 1 - s camera
// vertices) and connects x_{s-1} to x_s. Its density is
//   p_s = A_s * prod_{1 <= i < s} from_light[i] * prod_{i >= s} from_camera[i],
// from_light[i] the density of x_i sampled from x_{i-1}, from_camera[i] from x_{i+1}, and A_s how
// x_0 itself was drawn: nothing (from_camera[0] already counts it, s = 0), next event estimation's
// density nee0 (s = 1, when t >= 2: the light point is drawn by LightSet::sample from x_1, the cone
// for a sphere), or emission sampling's emit0 (s >= 2, and s = 1 with t = 1, where the light
// subpath's own point is connected to the camera). So the density used for every strategy is the
// one it samples with. The ratios p_{i+1} / p_i are nee0 / from_camera[0] (i = 0),
// emit0 from_light[1] / (nee0 from_camera[1]) (i = 1) and from_light[i] / from_camera[i] beyond
// (with k = 1, emit0 stands for nee0). Impossible strategies: s = 0 when the light cannot be hit
// (points, spots, delta directions); t = 0 (the lens is never hit); any connection at a vertex that
// scattered by a delta lobe; s = 1, t = 1 from a light at infinity. Densities of 0 (delta lobes)
// count as 1, as pbrt does: they appear only next to an impossible strategy, where they cancel.
//
// Merges. Merging at x_s (1 <= s <= k - 1) takes x_0..x_s from a light subpath and x_s..x_k from
// the camera subpath, and accepts the pair when the light subpath's x_s lies within r of the
// camera's. Its density is connection strategy s's times the light subpath's density of reaching
// x_s and the chance of landing within r: p_VM(s) = p_VC(s) * from_light[s] * eta, eta = pi r^2 N,
// N the light subpaths each camera subpath merges with. For s = 1 the light point x_0 is emission
// sampling's (emit0), not next event estimation's (nee0), so the connection density's nee0 is
// traded for emit0. A merge needs a non-delta x_s on a surface only: it is how light reaches a
// diffuse surface through a specular one (x_{s-1} delta), which no connection can. A medium
// vertex (participating media) has no merge: vcm merges photons on surfaces, so at a medium
// vertex the connections are the only techniques and the merge's term is absent from every sum.
//
// The weight is p^2 / sum over the possible techniques of p_i^2. Russian roulette is left out of
// the densities (as pbrt-v3): any weights that sum to 1 over the techniques of each path keep the
// estimator unbiased; test_render_bdpt.cpp and test_render_vcm.cpp check the sums.
//
// Cost: recursive tails (SmallVCM's dVCM, dVC, dVM in another form). Only the densities next to a
// connection or merge depend on it (the two ends' BSDFs in both directions); the rest of the sum
// is a fixed tail of each subpath. A MisPath therefore holds a window x_lo..x_hi around the
// technique and two tails: below = sum over i < lo of (p_i / p_lo)^2 w_i and above = sum over
// i > hi of (p_i / p_hi)^2 w_i, w_i the techniques at i (connection 1, merge (p_VM / p_VC)^2). Each
// subpath vertex carries its tail, grown by one step per vertex as the walk goes
// (mis_tail_below, mis_tail_above), so a connection or merge costs the same at any depth. A
// window over the whole path with empty tails is the explicit sum (the tests' oracle).
#include <array>

namespace sweeptrace {

// A tail of the sum, split into the connections' and the merges' terms (the planted defect
// DropMerges leaves the second out of the connections' weights).
struct MisTail {
    float conn = 0.0f, merge = 0.0f;
};

struct MisPath {
    static constexpr int kCapacity = 16;  // window entries (a connection's or merge's take <= 5)
    int k = 0;                            // x_0 .. x_k, x_k the camera
    int lo = 0, hi = 0;                   // the window's first and last vertex
    std::array<float, kCapacity> from_light{}, from_camera{};  // x_lo..x_hi (from_light[0] unused: emit0)
    std::array<char, kCapacity + 1> delta_flags{};  // x_{lo-1}..x_hi scattered by a delta lobe
    std::array<char, kCapacity> medium_flags{};     // x_lo..x_hi is a medium vertex (no merge there)
    float emit0 = 0.0f;           // emission sampling's density of x_0
    float nee0 = 0.0f;            // next event estimation's density of x_0 from x_1 (used when k >= 2)
    bool light_hittable = true;   // strategy s = 0 exists
    bool light_to_camera = true;  // strategy s = 1 exists when k = 1
    MisTail below, above;         // the strategies before x_lo and after x_hi (above)

    // Empties the window to x_lo..x_hi (0 <= lo <= hi <= k, hi - lo < kCapacity) of a k-path.
    void reset(int path_k, int first, int last);
    float& fl(int i) { return from_light[static_cast<std::size_t>(i - lo)]; }
    float& fc(int i) { return from_camera[static_cast<std::size_t>(i - lo)]; }
    char& delta(int i) { return delta_flags[static_cast<std::size_t>(i - lo + 1)]; }  // lo - 1 <= i <= hi
    char& medium(int i) { return medium_flags[static_cast<std::size_t>(i - lo)]; }
    float fl(int i) const { return from_light[static_cast<std::size_t>(i - lo)]; }
    float fc(int i) const { return from_camera[static_cast<std::size_t>(i - lo)]; }
    char delta(int i) const { return delta_flags[static_cast<std::size_t>(i - lo + 1)]; }
    char medium(int i) const { return medium_flags[static_cast<std::size_t>(i - lo)]; }
};

// Defects planted for the mutation tests (render/planted_defect.hpp): next event estimation (s = 1)
// left out of the sums, so the weights no longer sum to 1; or the merges left out of the
// connections' sums (bdpt's weights under merging), so they sum to more than 1.
enum class MisDefect { None, DropNee, DropMerges };

// The weight of connection strategy s (merge = false) or of merging at x_s (merge = true), over the
// connections and, with eta > 0, the merges. With eta = 0 there are no merges: bdpt's weights.
// lo <= s <= hi.
float mis_weight(const MisPath& path, int s, bool merge, float eta, MisDefect defect = MisDefect::None);

// One step of a tail: `below` of a window starting at x_i (path holds x_i and delta of x_{i-1})
// to the below of one starting at x_{i+1}. And `above` of a window ending at x_i (path holds
// x_{i-1} and x_i) to the above of one ending at x_{i-1}. The tails keep to k >= 2 paths' ratios
// (no window of a k = 1 path has a tail).
MisTail mis_tail_below(const MisPath& path, int i, const MisTail& below, float eta, MisDefect defect);
MisTail mis_tail_above(const MisPath& path, int i, const MisTail& above, float eta, MisDefect defect);

}  // namespace sweeptrace

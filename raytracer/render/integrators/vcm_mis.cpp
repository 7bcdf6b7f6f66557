#include "raytracer/render/integrators/vcm_mis.hpp"

#include <vector>

namespace sweeptrace {

namespace {

double vcm_remap0(float v) { return v != 0.0f ? double(v) : 1.0; }

bool vcm_merge_possible(const MisPath& p, int i, float eta) {
    return eta > 0.0f && i >= 1 && i <= p.k - 1 && !p.delta[static_cast<std::size_t>(i)];
}

// p_VM(i) / p_VC(i).
double vcm_merge_factor(const MisPath& p, int i, float eta) {
    const auto at = [&](int j) { return vcm_remap0(p.fwd[static_cast<std::size_t>(j)]); };
    double f = double(eta) * at(i);
    if (i == 1 && p.k >= 2) f *= at(0) / vcm_remap0(p.nee0);
    return f;
}

}  // namespace

float vcm_mis_weight(const MisPath& path, int s, bool merge, float eta, bool drop_merges) {
    if (merge ? !vcm_merge_possible(path, s, eta) : !bdpt_strategy_possible(path, s)) return 0.0f;
    // rel[i] = p_VC(i) / p_VC(s), along bdpt's chain of ratios.
    thread_local std::vector<double> rel;
    rel.assign(static_cast<std::size_t>(path.k + 1), 1.0);
    for (int i = s; i < path.k; ++i)
        rel[static_cast<std::size_t>(i + 1)] = rel[static_cast<std::size_t>(i)] * bdpt_density_ratio(path, i);
    for (int i = s - 1; i >= 0; --i)
        rel[static_cast<std::size_t>(i)] = rel[static_cast<std::size_t>(i + 1)] / bdpt_density_ratio(path, i);
    const bool count_merges = merge || !drop_merges;
    double sum = 0.0;
    for (int i = 0; i <= path.k; ++i) {
        const double r = rel[static_cast<std::size_t>(i)];
        if (bdpt_strategy_possible(path, i)) sum += r * r;
        if (count_merges && vcm_merge_possible(path, i, eta)) {
            const double m = r * vcm_merge_factor(path, i, eta);
            sum += m * m;
        }
    }
    const double own = merge ? vcm_merge_factor(path, s, eta) : 1.0;
    return static_cast<float>(own * own / sum);
}

}  // namespace sweeptrace

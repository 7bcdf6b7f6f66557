#include "raytracer/render/integrators/bdpt_mis.hpp"

namespace sweeptrace {

namespace {

float remap0(float v) { return v != 0.0f ? v : 1.0f; }

}  // namespace

bool bdpt_strategy_possible(const MisPath& p, int i) {
    if (i < 0 || i > p.k) return false;
    if (i == 0) return p.light_hittable;
    if (i == 1 && p.k == 1 && !p.light_to_camera) return false;
    if (p.delta[static_cast<std::size_t>(i - 1)]) return false;
    return i == p.k || !p.delta[static_cast<std::size_t>(i)];
}

// p_{i+1} / p_i.
float bdpt_density_ratio(const MisPath& p, int i) {
    const auto at = [](const std::vector<float>& v, int j) { return remap0(v[static_cast<std::size_t>(j)]); };
    const float a1 = p.k >= 2 ? remap0(p.nee0) : at(p.fwd, 0);
    if (i == 0) return a1 / at(p.rev, 0);
    if (i == 1) return at(p.fwd, 0) * at(p.fwd, 1) / (a1 * at(p.rev, 1));
    return at(p.fwd, i) / at(p.rev, i);
}

float bdpt_mis_weight(const MisPath& path, int s, bool drop_nee) {
    if (!bdpt_strategy_possible(path, s)) return 0.0f;
    const auto counted = [&](int i) { return bdpt_strategy_possible(path, i) && !(drop_nee && i == 1); };
    float sum = 1.0f;
    float r = 1.0f;
    for (int i = s; i < path.k; ++i) {
        r *= bdpt_density_ratio(path, i);
        if (counted(i + 1)) sum += r * r;
    }
    r = 1.0f;
    for (int i = s - 1; i >= 0; --i) {
        r /= bdpt_density_ratio(path, i);
        if (counted(i)) sum += r * r;
    }
    return 1.0f / sum;
}

}  // namespace sweeptrace

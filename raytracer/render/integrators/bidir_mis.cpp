#include "raytracer/render/integrators/bidir_mis.hpp"

namespace sweeptrace {

namespace {

double remap0(float v) { return v != 0.0f ? double(v) : 1.0; }

bool connection_possible(const MisPath& p, int i) {
    if (i < 0 || i > p.k) return false;
    if (i == 0) return p.light_hittable;
    if (i == 1 && p.k == 1 && !p.light_to_camera) return false;
    if (p.delta[static_cast<std::size_t>(i - 1)]) return false;
    return i == p.k || !p.delta[static_cast<std::size_t>(i)];
}

bool merge_possible(const MisPath& p, int i, float eta) {
    return eta > 0.0f && i >= 1 && i <= p.k - 1 && !p.delta[static_cast<std::size_t>(i)];
}

// p_{i+1} / p_i of the connection strategies.
double density_ratio(const MisPath& p, int i) {
    const auto at = [](const std::vector<float>& v, int j) { return remap0(v[static_cast<std::size_t>(j)]); };
    const double a1 = p.k >= 2 ? remap0(p.nee0) : at(p.from_light, 0);
    if (i == 0) return a1 / at(p.from_camera, 0);
    if (i == 1) return at(p.from_light, 0) * at(p.from_light, 1) / (a1 * at(p.from_camera, 1));
    return at(p.from_light, i) / at(p.from_camera, i);
}

// p_VM(i) / p_VC(i).
double merge_factor(const MisPath& p, int i, float eta) {
    double f = double(eta) * remap0(p.from_light[static_cast<std::size_t>(i)]);
    if (i == 1 && p.k >= 2) f *= remap0(p.from_light[0]) / remap0(p.nee0);
    return f;
}

}  // namespace

float mis_weight(const MisPath& path, int s, bool merge, float eta, MisDefect defect) {
    if (merge ? !merge_possible(path, s, eta) : !connection_possible(path, s)) return 0.0f;
    // rel = p_VC(i) / p_VC(s), along the chain of ratios out from s in both directions.
    const bool count_merges = merge || defect != MisDefect::DropMerges;
    const auto term = [&](int i, double rel) {
        double t = 0.0;
        if (connection_possible(path, i) && !(defect == MisDefect::DropNee && i == 1 && i != s)) t += rel * rel;
        if (count_merges && merge_possible(path, i, eta)) {
            const double m = rel * merge_factor(path, i, eta);
            t += m * m;
        }
        return t;
    };
    double sum = term(s, 1.0);
    double rel = 1.0;
    for (int i = s; i < path.k; ++i) {
        rel *= density_ratio(path, i);
        sum += term(i + 1, rel);
    }
    rel = 1.0;
    for (int i = s - 1; i >= 0; --i) {
        rel /= density_ratio(path, i);
        sum += term(i, rel);
    }
    const double own = merge ? merge_factor(path, s, eta) : 1.0;
    return static_cast<float>(own * own / sum);
}

void gather_mis_path(MisPath& m, int k, std::span<const PathVertex> light, std::span<const PathVertex> cam,
                     const LightSet& lights) {
    m.k = k;
    const auto n = static_cast<std::size_t>(k + 1);
    m.from_light.assign(n, 0.0f);
    m.from_camera.assign(n, 0.0f);
    m.delta.assign(n, 0);
    // A light subpath's vertex was sampled from x_{i-1} (its own walk) and would be from x_{i+1}
    // by the camera's; a camera subpath's the other way round.
    for (std::size_t i = 0; i < light.size() && i < n; ++i) {
        const PathVertex& v = light[i];
        m.from_light[i] = v.pdf_own;
        m.from_camera[i] = v.pdf_other;
        m.delta[i] = v.delta;
    }
    for (std::size_t j = 0; j < cam.size() && j < n; ++j) {
        const std::size_t i = n - 1 - j;
        const PathVertex& v = cam[j];
        m.from_light[i] = v.pdf_other;
        m.from_camera[i] = v.pdf_own;
        m.delta[i] = v.delta;
    }
    if (!light.empty()) {
        const PathVertex& l0 = light.front();
        m.nee0 = l0.pdf_nee;
        m.light_hittable = !l0.delta_position && !l0.delta_direction &&
                           (!l0.at_infinity || lights.light_is_found_at_infinity(l0.light));
        m.light_to_camera = !l0.at_infinity;
    }
}

}  // namespace sweeptrace

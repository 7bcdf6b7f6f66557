#include "raytracer/render/integrators/bidir_mis.hpp"

#include <stdexcept>

namespace sweeptrace {

void MisPath::reset(int path_k, int first, int last) {
    if (!(0 <= first && first <= last && last <= path_k && last - first < kCapacity))
        throw std::logic_error("MisPath: window outside the path or over capacity");
    k = path_k;
    lo = first;
    hi = last;
    from_light.fill(0.0f);
    from_camera.fill(0.0f);
    delta_flags.fill(0);
    medium_flags.fill(0);
    below = above = MisTail{};
}

namespace {

double remap0(float v) { return v != 0.0f ? double(v) : 1.0; }

bool connection_possible(const MisPath& p, int i) {
    if (i < 0 || i > p.k) return false;
    if (i == 0) return p.light_hittable;
    if (i == 1 && p.k == 1 && !p.light_to_camera) return false;
    if (p.delta(i - 1)) return false;
    return i == p.k || !p.delta(i);
}

bool merge_possible(const MisPath& p, int i, float eta) {
    return eta > 0.0f && i >= 1 && i <= p.k - 1 && !p.delta(i) && !p.medium(i);
}

// p_{i+1} / p_i of the connection strategies.
double density_ratio(const MisPath& p, int i) {
    const double a1 = p.k >= 2 ? remap0(p.nee0) : remap0(p.emit0);
    if (i == 0) return a1 / remap0(p.fc(0));
    if (i == 1) return remap0(p.emit0) * remap0(p.fl(1)) / (a1 * remap0(p.fc(1)));
    return remap0(p.fl(i)) / remap0(p.fc(i));
}

// p_VM(i) / p_VC(i).
double merge_factor(const MisPath& p, int i, float eta) {
    double f = double(eta) * remap0(p.fl(i));
    if (i == 1 && p.k >= 2) f *= remap0(p.emit0) / remap0(p.nee0);
    return f;
}

// The techniques at x_i relative to connection i: connection's and merge's squared.
struct Terms {
    double conn, merge;
};
Terms terms(const MisPath& p, int i, float eta, bool drop_connection) {
    Terms t{0.0, 0.0};
    if (!drop_connection && connection_possible(p, i)) t.conn = 1.0;
    if (merge_possible(p, i, eta)) {
        const double m = merge_factor(p, i, eta);
        t.merge = m * m;
    }
    return t;
}

}  // namespace

float mis_weight(const MisPath& path, int s, bool merge, float eta, MisDefect defect) {
    if (merge ? !merge_possible(path, s, eta) : !connection_possible(path, s)) return 0.0f;
    // rel = p_VC(i) / p_VC(s), along the chain of ratios out from s in both directions.
    const bool count_merges = merge || defect != MisDefect::DropMerges;
    const auto term = [&](int i, double rel) {
        const Terms t = terms(path, i, eta, defect == MisDefect::DropNee && i == 1 && i != s);
        return rel * rel * (t.conn + (count_merges ? t.merge : 0.0));
    };
    const auto tail = [&](const MisTail& t, double rel) {
        return rel * rel * (double(t.conn) + (count_merges ? double(t.merge) : 0.0));
    };
    double sum = term(s, 1.0);
    double rel = 1.0;
    for (int i = s; i < path.hi; ++i) {
        rel *= density_ratio(path, i);
        sum += term(i + 1, rel);
    }
    sum += tail(path.above, rel);
    rel = 1.0;
    for (int i = s - 1; i >= path.lo; --i) {
        rel /= density_ratio(path, i);
        sum += term(i, rel);
    }
    sum += tail(path.below, rel);
    const double own = merge ? merge_factor(path, s, eta) : 1.0;
    return static_cast<float>(own * own / sum);
}

// below_{i+1} = (below_i + w_i) (p_i / p_{i+1})^2.
MisTail mis_tail_below(const MisPath& path, int i, const MisTail& below, float eta, MisDefect defect) {
    const Terms t = terms(path, i, eta, defect == MisDefect::DropNee && i == 1);
    const double r = density_ratio(path, i);
    const double f = 1.0 / (r * r);
    return {static_cast<float>((double(below.conn) + t.conn) * f), static_cast<float>((double(below.merge) + t.merge) * f)};
}

// above_{i-1} = (above_i + w_i) (p_i / p_{i-1})^2.
MisTail mis_tail_above(const MisPath& path, int i, const MisTail& above, float eta, MisDefect defect) {
    const Terms t = terms(path, i, eta, defect == MisDefect::DropNee && i == 1);
    const double r = density_ratio(path, i - 1);
    const double f = r * r;
    return {static_cast<float>((double(above.conn) + t.conn) * f), static_cast<float>((double(above.merge) + t.merge) * f)};
}

}  // namespace sweeptrace

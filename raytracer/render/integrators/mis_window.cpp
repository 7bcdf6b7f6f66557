#include "raytracer/render/integrators/mis_window.hpp"

namespace sweeptrace {

namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

}  // namespace

LightVertexMis light_origin_mis(const PathVertex& x0, bool light_hittable) {
    LightVertexMis mis;
    mis.pdf_own = mis.emit0 = x0.pdf_own;
    mis.nee0 = x0.pdf_nee;
    mis.flags = light_hittable ? LightVertexMis::kLightHittable : 0;
    return mis;
}

LightVertexMis light_vertex_mis(std::span<const PathVertex> light, int b, bool light_hittable, float eta,
                                MisDefect defect) {
    const PathVertex& v = light[at(b)];
    const PathVertex& prev = light[at(b - 1)];
    LightVertexMis mis = light_origin_mis(light[0], light_hittable);
    mis.pdf_own = v.pdf_own;
    mis.prev_pdf_own = prev.pdf_own;
    // x_{b-1} as the camera's direction reaches it from x_b: over the same segment, the same flight.
    mis.prev_area = area_density(1.0f, v.point(), prev) * flight_density(v.mis_tr, prev);
    mis.depth = static_cast<std::uint16_t>(b);
    if (prev.delta) mis.flags |= LightVertexMis::kDeltaPrev;
    if (v.in_medium()) mis.flags |= LightVertexMis::kMedium;
    if (prev.in_medium()) mis.flags |= LightVertexMis::kMediumPrev;
    if (b >= 2 && light[at(b - 2)].delta) mis.flags |= LightVertexMis::kDeltaPrevPrev;
    if (b >= 2) {
        // The tail before x_{b-1}: light[b-1]'s (before x_{b-2}) and x_{b-2}'s own techniques, its
        // density from x_{b-1} now known. k only has to exceed b: every later technique's path does.
        MisPath m;
        m.reset(b + 1, b - 2, b - 2);
        const PathVertex& pp = light[at(b - 2)];
        m.emit0 = mis.emit0;
        m.nee0 = mis.nee0;
        m.light_hittable = light_hittable;
        m.fl(b - 2) = pp.pdf_own;
        m.fc(b - 2) = pp.pdf_other;
        m.delta(b - 2) = pp.delta;
        m.medium(b - 2) = pp.in_medium();
        if (b >= 3) m.delta(b - 3) = light[at(b - 3)].delta;
        mis.below = mis_tail_below(m, b - 2, prev.light_mis.below, eta, defect);
    }
    return mis;
}

MisTail camera_vertex_above(std::span<const PathVertex> cam, int j, float eta, MisDefect defect) {
    if (j < 3) return {};
    // Any k whose indices keep the ratios past x_1: cam[m] is x_{j+2-m}, the lens x_k.
    const int k = j + 2;
    MisPath m;
    m.reset(k, 4, 5);
    for (int i = 4; i <= 5; ++i) {
        const PathVertex& v = cam[at(k - i)];
        m.fl(i) = v.pdf_other;
        m.fc(i) = v.pdf_own;
        m.delta(i) = v.delta;
        m.medium(i) = v.in_medium();
    }
    return mis_tail_above(m, 5, cam[at(j - 1)].above, eta, defect);
}

void put_light_end(MisPath& m, const LightVertexMis& y, float pdf_to_prev) {
    const int b = y.depth;
    m.emit0 = y.emit0;
    m.nee0 = y.nee0;
    m.light_hittable = (y.flags & LightVertexMis::kLightHittable) != 0;
    m.fl(b) = y.pdf_own;
    m.medium(b) = (y.flags & LightVertexMis::kMedium) != 0;
    if (b == 0) return;
    m.fl(b - 1) = y.prev_pdf_own;
    m.fc(b - 1) = pdf_to_prev * y.prev_area;
    m.delta(b - 1) = (y.flags & LightVertexMis::kDeltaPrev) != 0;
    m.medium(b - 1) = (y.flags & LightVertexMis::kMediumPrev) != 0;
    if (b >= 2) m.delta(b - 2) = (y.flags & LightVertexMis::kDeltaPrevPrev) != 0;
    m.below = y.below;
}

void put_camera_end(MisPath& m, std::span<const PathVertex> cam, int j, int s, float fl_s, float fl_next,
                    bool keep_delta) {
    const PathVertex& z = cam[at(j)];
    m.fl(s) = fl_s;
    m.fc(s) = z.pdf_own;
    m.delta(s) = keep_delta && z.delta;
    m.medium(s) = z.in_medium();
    if (j >= 1) {
        const PathVertex& next = cam[at(j - 1)];
        m.fl(s + 1) = j >= 2 ? fl_next : next.pdf_other;
        m.fc(s + 1) = next.pdf_own;
        m.delta(s + 1) = next.delta;
        m.medium(s + 1) = next.in_medium();
    }
    if (j >= 2) {
        const PathVertex& after = cam[at(j - 2)];
        m.fl(s + 2) = after.pdf_other;
        m.fc(s + 2) = after.pdf_own;
        m.delta(s + 2) = after.delta;
        m.medium(s + 2) = after.in_medium();
        m.above = z.above;
    }
}

}  // namespace sweeptrace

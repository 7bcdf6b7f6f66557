// The recursive MIS (bidir_mis.hpp's tails, mis_window.hpp) against the explicit sums: random light
// and camera subpaths (densities over four decades, delta vertices with the densities next to them
// 0 as the walks store them, points and normals at random), each vertex's tail grown by the walks'
// own functions, and every connection, merge, light-tracing splat (t = 1), emitter hit (s = 0) and
// next event estimation (s = 1) weighted from its window alone; the weight must be the one of the
// whole path's explicit sum (a window over the whole path with empty tails), for each planted
// defect too. Medium vertices among them (no cosine, a flight density in their densities, no
// merge): a walk that loses either is caught. A wrong step of a tail (a ratio the wrong way
// round) is caught.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "raytracer/render/integrators/bidir_mis.hpp"
#include "raytracer/render/integrators/mis_window.hpp"
#include "raytracer/render/integrators/path_vertex.hpp"

using namespace sweeptrace;

namespace {

struct Subpaths {
    std::vector<PathVertex> light, cam;
    bool light_hittable = true;
};

float random_density(std::mt19937& rng) { return std::pow(10.0f, std::uniform_real_distribution<float>(-2.0f, 2.0f)(rng)); }

glm::vec3 random_point(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    return {u(rng), u(rng), u(rng)};
}

// Walks of random densities, the MIS quantities set as bdpt.cpp's walks set them.
// The walks' MIS quantities as a planted slip would leave them: a medium vertex's flight
// density dropped from its predecessor's density (prev_area), or its no-merge mark lost.
enum class WalkSlip { None, NoFlightDensity, MergeAtMedium };

Subpaths random_subpaths(std::mt19937& rng, float eta, MisDefect defect, WalkSlip slip = WalkSlip::None) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Subpaths sp;
    const int nl = 1 + static_cast<int>(unit(rng) * 6.0f), nc = 1 + static_cast<int>(unit(rng) * 6.0f);
    sp.light_hittable = unit(rng) < 0.7f;
    sp.light.resize(static_cast<std::size_t>(nl));
    sp.cam.resize(static_cast<std::size_t>(nc));
    for (auto* path : {&sp.light, &sp.cam})
        for (std::size_t i = 0; i < path->size(); ++i) {
            PathVertex& v = (*path)[i];
            v.kind = i > 0 ? PathVertex::Kind::Surface : path == &sp.light ? PathVertex::Kind::Light : PathVertex::Kind::Camera;
            v.hit.point = random_point(rng);
            v.hit.normal = glm::normalize(random_point(rng) + glm::vec3(0.0f, 0.0f, 1e-3f));
            v.pdf_own = i > 0 || path == &sp.light ? random_density(rng) : 0.0f;
            v.pdf_other = random_density(rng);
            // A delta lobe at an inner vertex: the densities it decided are 0.
            if (i > 0 && i + 1 < path->size() && unit(rng) < 0.25f) v.delta = true;
            // Participating media: the segment from its predecessor crossed a medium (its MIS
            // transmittance), and an inner vertex may be a medium vertex (no normal, no merge).
            if (i > 0 && unit(rng) < 0.4f) v.mis_tr = glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(1e-3f);
            if (i > 0 && !v.delta && unit(rng) < 0.25f) {
                v.kind = PathVertex::Kind::Medium;
                v.hit.normal = glm::vec3(0.0f);
                v.sigma_t = glm::vec3(random_density(rng), random_density(rng), random_density(rng));
            }
        }
    for (auto* path : {&sp.light, &sp.cam})
        for (std::size_t i = 1; i + 1 < path->size(); ++i)
            if ((*path)[i].delta) (*path)[i + 1].pdf_own = (*path)[i - 1].pdf_other = 0.0f;
    sp.cam[0].pdf_other = 0.0f;  // the lens is never hit
    sp.light[0].pdf_nee = random_density(rng);
    sp.light[0].light_mis = light_origin_mis(sp.light[0], sp.light_hittable);
    for (int b = 1; b < nl; ++b) {
        LightVertexMis& mis = sp.light[static_cast<std::size_t>(b)].light_mis;
        mis = light_vertex_mis(sp.light, b, sp.light_hittable, eta, defect);
        const PathVertex& v = sp.light[static_cast<std::size_t>(b)];
        if (slip == WalkSlip::NoFlightDensity) mis.prev_area /= flight_density(v.mis_tr, sp.light[static_cast<std::size_t>(b - 1)]);
        if (slip == WalkSlip::MergeAtMedium) mis.flags &= static_cast<std::uint8_t>(~LightVertexMis::kMediumPrev);
    }
    for (int j = 1; j < nc; ++j) sp.cam[static_cast<std::size_t>(j)].above = camera_vertex_above(sp.cam, j, eta, defect);
    return sp;
}

// The whole path light[0..s) + x_s .. x_k from cam[j..0] (j = k - s), as the subpaths sampled it;
// the technique's own entries are the caller's.
MisPath whole_path(const Subpaths& sp, int s, int j, bool light_to_camera) {
    MisPath m;
    const int k = s + j;
    m.reset(k, 0, k);
    for (int i = 0; i < s; ++i) {
        const PathVertex& v = sp.light[static_cast<std::size_t>(i)];
        m.fl(i) = v.pdf_own;
        m.fc(i) = v.pdf_other;
        m.delta(i) = v.delta;
        m.medium(i) = v.in_medium();
    }
    for (int c = 0; c <= j; ++c) {
        const PathVertex& v = sp.cam[static_cast<std::size_t>(c)];
        m.fl(k - c) = v.pdf_other;
        m.fc(k - c) = v.pdf_own;
        m.delta(k - c) = v.delta;
        m.medium(k - c) = v.in_medium();
    }
    m.emit0 = sp.light[0].pdf_own;
    m.nee0 = sp.light[0].pdf_nee;
    m.light_hittable = sp.light_hittable;
    m.light_to_camera = light_to_camera;
    return m;
}

// light[b - 1]'s density from light[b] by a direction density `pdf` there: per unit area (no
// cosine at a medium vertex), over the segment's flight (subpath_flight.hpp).
float toward_prev(float pdf, const Subpaths& sp, int b) {
    const PathVertex& y = sp.light[static_cast<std::size_t>(b)];
    const PathVertex& prev = sp.light[static_cast<std::size_t>(b - 1)];
    return area_density(pdf, y.point(), prev) * flight_density(y.mis_tr, prev);
}

struct Checked {
    int techniques = 0, nonzero = 0;
    double worst = 0.0;
};

void compare(const MisPath& whole, const MisPath& window, int s, bool merge, float eta, MisDefect defect, Checked& c) {
    const float w = mis_weight(whole, s, merge, eta, defect);
    const float r = mis_weight(window, s, merge, eta, defect);
    c.worst = std::max(c.worst, std::abs(double(w) - double(r)) / std::max(1e-3, double(w)));
    ++c.techniques;
    c.nonzero += w > 1e-3f ? 1 : 0;
}

void check_all(std::mt19937& rng, float eta, MisDefect defect, Checked& c, WalkSlip slip = WalkSlip::None) {
    const Subpaths sp = random_subpaths(rng, eta, defect, slip);
    const int nl = static_cast<int>(sp.light.size()), nc = static_cast<int>(sp.cam.size());
    const float x1 = random_density(rng), x2 = random_density(rng), x3 = random_density(rng), x4 = random_density(rng);
    const bool to_camera = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng) < 0.7f;
    // Connections: light[b] (x_{s-1}) with cam[j] (x_s), s = b + 1 >= 2, t = j + 1 >= 2; a
    // delta light vertex never connects.
    for (int b = 1; b < nl; ++b)
        for (int j = 1; j < nc; ++j) {
            const PathVertex& y = sp.light[static_cast<std::size_t>(b)];
            if (y.delta) continue;
            const int s = b + 1, k = s + j;
            const float pdf_wo = x2;  // y's BSDF toward light[b - 1], per solid angle
            MisPath whole = whole_path(sp, s, j, to_camera);
            whole.delta(s - 1) = whole.delta(s) = 0;
            whole.fc(s - 1) = x1;
            whole.fc(s - 2) = toward_prev(pdf_wo, sp, b);
            whole.fl(s) = x3;
            if (j >= 2) whole.fl(s + 1) = x4;
            MisPath win;
            win.reset(k, b - 1, std::min(k, s + 2));
            win.light_to_camera = to_camera;
            put_light_end(win, y.light_mis, pdf_wo);
            win.fc(b) = x1;
            put_camera_end(win, sp.cam, j, s, x3, x4);
            compare(whole, win, s, false, eta, defect, c);
        }
    // Merges: light[s] (s >= 1, not delta) at cam[j] (j >= 1).
    for (int s = 1; s < nl; ++s)
        for (int j = 1; j < nc; ++j) {
            const PathVertex& y = sp.light[static_cast<std::size_t>(s)];
            if (y.delta) continue;
            const int k = s + j;
            const float pdf_wi = x2;  // the camera vertex's BSDF toward light[s - 1], per solid angle
            MisPath whole = whole_path(sp, s, j, to_camera);
            whole.fl(s) = y.pdf_own;
            whole.delta(s) = 0;
            whole.fc(s - 1) = toward_prev(pdf_wi, sp, s);
            if (j >= 2) whole.fl(s + 1) = x4;
            MisPath win;
            win.reset(k, s - 1, std::min(k, s + 2));
            win.light_to_camera = to_camera;
            put_light_end(win, y.light_mis, pdf_wi);
            put_camera_end(win, sp.cam, j, s, y.pdf_own, x4);
            compare(whole, win, s, true, eta, defect, c);
        }
    // Light tracing (t = 1): light[b] to the lens, k = s = b + 1.
    for (int b = 0; b < nl; ++b) {
        const PathVertex& y = sp.light[static_cast<std::size_t>(b)];
        if (y.delta) continue;
        const int s = b + 1;
        MisPath whole = whole_path(sp, s, 0, to_camera);
        whole.delta(s - 1) = 0;
        whole.fc(s - 1) = x1;
        if (s >= 2) whole.fc(s - 2) = toward_prev(x2, sp, b);
        MisPath win;
        win.reset(s, std::max(0, b - 1), s);
        win.light_to_camera = to_camera;
        put_light_end(win, y.light_mis, x2);
        win.fc(b) = x1;
        compare(whole, win, s, false, eta, defect, c);
    }
    // An emitter hit at cam[j] (s = 0, k = j) and next event estimation from it (s = 1, k = j + 1):
    // x_0 is new, from the camera subpath alone.
    for (int j = 1; j < nc; ++j) {
        for (const int s : {0, 1}) {
            const int k = s + j;
            Subpaths one = sp;
            one.light.resize(1);
            MisPath whole = whole_path(one, s, j, to_camera);
            whole.delta(s) = 0;
            if (s == 1) whole.fc(0) = x1;
            whole.fl(s) = x3;
            if (j >= 2) whole.fl(s + 1) = x4;
            MisPath win;
            win.reset(k, 0, std::min(k, s + 2));
            win.emit0 = whole.emit0;
            win.nee0 = whole.nee0;
            win.light_hittable = whole.light_hittable;
            win.light_to_camera = to_camera;
            if (s == 1) win.fc(0) = x1;
            put_camera_end(win, sp.cam, j, s, x3, x4);
            compare(whole, win, s, false, eta, defect, c);
        }
    }
}

}  // namespace

TEST_CASE("bidir MIS: the recursive weights of every technique are the explicit sums' on random subpaths",
          "[bdpt][vcm][mis]") {
    std::mt19937 rng(2024);
    Checked c;
    for (int n = 0; n < 1500; ++n) {
        const float eta = n % 3 == 0 ? 0.0f : random_density(rng);
        for (const MisDefect defect : {MisDefect::None, MisDefect::DropNee, MisDefect::DropMerges}) check_all(rng, eta, defect, c);
    }
    INFO("techniques " << c.techniques << ", weights > 1e-3 " << c.nonzero << ", worst relative error " << c.worst);
    CHECK(c.techniques > 50000);
    CHECK(c.nonzero > 10000);
    CHECK(c.worst < 1e-4);
}

// A tail grown with the ratio upside down (the step of the other direction) gives other weights.
TEST_CASE("bidir MIS: a tail grown the wrong way is caught", "[bdpt][vcm][mis]") {
    std::mt19937 rng(7);
    int differ = 0, tested = 0;
    for (int n = 0; n < 300; ++n) {
        MisPath whole;
        const int k = 6;
        whole.reset(k, 0, k);
        for (int i = 0; i <= k; ++i) {
            whole.fl(i) = random_density(rng);
            whole.fc(i) = random_density(rng);
        }
        whole.emit0 = whole.fl(0);
        whole.nee0 = random_density(rng);
        const float eta = random_density(rng);
        // Merge at x_4: the window x_3..x_6, the tail below x_3 grown by the right and the wrong step.
        MisTail right, wrong;
        for (int i = 0; i < 3; ++i) {
            right = mis_tail_below(whole, i, right, eta, MisDefect::None);
            wrong = mis_tail_above(whole, i + 1, wrong, eta, MisDefect::None);
        }
        MisPath win = whole;
        win.reset(k, 3, k);
        for (int i = 3; i <= k; ++i) {
            win.fl(i) = whole.fl(i);
            win.fc(i) = whole.fc(i);
        }
        win.emit0 = whole.emit0;
        win.nee0 = whole.nee0;
        const float w = mis_weight(whole, 4, true, eta);
        win.below = right;
        const float r = mis_weight(win, 4, true, eta);
        win.below = wrong;
        const float x = mis_weight(win, 4, true, eta);
        ++tested;
        CHECK(r == Approx(w).epsilon(1e-4));
        differ += std::abs(x - w) > 1e-3f * std::max(w, 1e-3f) ? 1 : 0;
    }
    CHECK(differ > tested / 2);
}

// The walks' slips with media (WalkSlip): the windows' weights leave the explicit sums'.
TEST_CASE("bidir MIS: a medium vertex's flight density or no-merge mark lost by the walk is caught", "[bdpt][vcm][mis]") {
    for (const WalkSlip slip : {WalkSlip::NoFlightDensity, WalkSlip::MergeAtMedium}) {
        std::mt19937 rng(99);
        Checked c;
        for (int n = 0; n < 1500; ++n) check_all(rng, n % 3 == 0 ? 0.0f : random_density(rng), MisDefect::None, c, slip);
        INFO("slip " << static_cast<int>(slip) << ": techniques " << c.techniques << ", worst relative error " << c.worst);
        CHECK(c.worst > 1e-2);
    }
}

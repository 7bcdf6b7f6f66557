#include "raytracer/render/media/tracking.hpp"

#include <algorithm>

namespace sweeptrace {

namespace {

// A distance to the next tentative collision at rate mu, from u in [0, 1).
float exponential_step(float mu, float u) { return -std::log1p(-u) / mu; }

// A collision's factor `f` (per channel, relative to the hero's density) on the path: r_u takes
// it and is brought back to mean 1, beta takes it divided by the new mean (tracking.hpp).
void take_factor(const glm::vec3& f, glm::vec3& beta, glm::vec3& r_u) {
    const glm::vec3 r = r_u * f;
    const float mean = mean_of_channels(r);
    beta *= f / mean;
    r_u = r / mean;
}

}  // namespace

FlightResult delta_track(const MediumModel& m, const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, int hero,
                         Rng& rng, glm::vec3& beta, glm::vec3& r_u, bool emission) {
    FlightResult out;
    m.majorants(o, d, tmin, tmax, [&](float t0, float t1, float mu) {
        float t = t0;
        for (;;) {
            t += exponential_step(mu, rng.uniform());
            if (!(t < t1)) return true;  // past this stretch: the next one starts afresh (memoryless)
            ++out.collisions;
            const MediumPoint p = m.at(o + t * d);
            if (emission && p.emission != glm::vec3(0.0f))
                out.emitted += beta * p.sigma_a * p.emission / mu;
            const glm::vec3 sigma_n = glm::max(glm::vec3(mu) - p.sigma_a - p.sigma_s, glm::vec3(0.0f));
            // The hero's probabilities, normalised (they sum to 1 unless rounding put sigma_t a
            // hair above the bound).
            const float pa = p.sigma_a[hero], ps = p.sigma_s[hero], pn = sigma_n[hero];
            const float u = rng.uniform() * (pa + ps + pn);
            if (u < pa) {
                out.event = Flight::Absorbed;
                out.t = t;
                return false;
            }
            if (u < pa + ps) {
                take_factor(p.sigma_s / ps, beta, r_u);
                out.event = Flight::Scattered;
                out.t = t;
                return false;
            }
            take_factor(sigma_n / pn, beta, r_u);
        }
    });
    return out;
}

glm::vec3 ratio_track(const MediumModel& m, const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, Rng& rng,
                      std::uint64_t* collisions) {
    glm::vec3 tr(1.0f);
    m.majorants(o, d, tmin, tmax, [&](float t0, float t1, float mu) {
        if (!std::isfinite(t1)) {  // an unbounded homogeneous stretch: exp(-sigma_t inf), exactly
            const glm::vec3 st = m.medium().sigma_a + m.medium().sigma_s;
            for (int c = 0; c < 3; ++c)
                if (st[c] > 0.0f) tr[c] = 0.0f;
            return tr != glm::vec3(0.0f);
        }
        float t = t0;
        for (;;) {
            t += exponential_step(mu, rng.uniform());
            if (!(t < t1)) return true;
            if (collisions) ++*collisions;
            const MediumPoint p = m.at(o + t * d);
            tr *= glm::max(glm::vec3(1.0f) - (p.sigma_a + p.sigma_s) / mu, glm::vec3(0.0f));
            // Russian roulette on a weak estimate (pbrt-v4's rule): survival 1/4 below 0.05,
            // weighted by 4, so dense media do not walk on for a negligible contribution.
            if (std::max(tr.x, std::max(tr.y, tr.z)) < 0.05f) {
                if (rng.uniform() < 0.75f) tr = glm::vec3(0.0f);
                else tr *= 4.0f;
            }
            if (tr == glm::vec3(0.0f)) return false;
        }
    });
    return tr;
}

glm::vec3 transmittance(const MediumModel& m, const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, Rng& rng) {
    if (!m.homogeneous()) return ratio_track(m, o, d, tmin, tmax, rng);
    if (!(tmin < tmax)) return glm::vec3(1.0f);
    const glm::vec3 st = m.medium().sigma_a + m.medium().sigma_s;
    glm::vec3 tr;
    for (int c = 0; c < 3; ++c) tr[c] = st[c] > 0.0f ? std::exp(-st[c] * (tmax - tmin)) : 1.0f;
    return tr;
}

}  // namespace sweeptrace

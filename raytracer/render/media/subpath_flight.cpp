#include "raytracer/render/media/subpath_flight.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sweeptrace {

namespace {

// The flight's running f and per-channel density p (subpath_flight.hpp), kept at mean(p) = 1:
// only f / mean(p) matters, and long grid walks would otherwise underflow.
struct FlightRatio {
    glm::vec3 f{1.0f}, p{1.0f};
    void take(const glm::vec3& fi, const glm::vec3& pi) {
        f *= fi;
        p *= pi;
        const float s = mean_of_channels(p);
        if (s > 0.0f) {
            f /= s;
            p /= s;
        }
    }
    glm::vec3 weight() const {
        const float s = mean_of_channels(p);
        return s > 0.0f ? f / s : glm::vec3(0.0f);
    }
};

glm::vec3 exp_of(const glm::vec3& sigma_t, float d) {
    glm::vec3 tr;
    for (int c = 0; c < 3; ++c) tr[c] = sigma_t[c] > 0.0f ? std::exp(-sigma_t[c] * d) : 1.0f;
    return tr;
}

// One medium's stretch [tmin, tmax) of the unit-direction ray o + t d, channel c: true and `t`
// set when the flight scatters in it. `emitted` (null: not estimated) gathers the medium's
// emission on the stretch, per unit throughput before the flight (subpath_flight.hpp).
bool stretch(const MediumModel& m, const glm::vec3& o, const glm::vec3& d, float tmin, float tmax, int c, Rng& rng,
             FlightRatio& ratio, glm::vec3& mis_tr, glm::vec3& sigma_t, float& t_out, glm::vec3* emitted) {
    if (m.homogeneous()) {
        const MediumPoint mp = m.at(o);
        const glm::vec3 st = mp.sigma_a + mp.sigma_s;
        const float u = rng.uniform();
        const float t = st[c] > 0.0f ? tmin - std::log1p(-u) / st[c] : std::numeric_limits<float>::infinity();
        if (t < tmax) {
            const glm::vec3 tr = exp_of(st, t - tmin);
            if (emitted != nullptr) {
                // The point's emission over the flight's density of it: T sigma_a Le / p(x).
                FlightRatio e = ratio;
                e.take(mp.sigma_a * mp.emission * tr, st * tr);
                *emitted += e.weight();
            }
            ratio.take(mp.sigma_s * tr, st * tr);
            mis_tr *= tr;
            sigma_t = st;
            t_out = t;
            return true;
        }
        const glm::vec3 tr = exp_of(st, tmax - tmin);  // 0 for an unbounded stretch of any extinction
        ratio.take(tr, tr);
        mis_tr *= tr;
        return false;
    }
    bool scattered = false;
    m.majorants(o, d, tmin, tmax, [&](float t0, float t1, float mu) {
        float t = t0;
        for (;;) {
            t += -std::log1p(-rng.uniform()) / mu;
            if (!(t < t1)) return true;
            const MediumPoint mp = m.at(o + t * d);
            const glm::vec3 st = mp.sigma_a + mp.sigma_s;
            // Every tentative collision's emission, before its event is chosen (tracking.hpp).
            if (emitted != nullptr) *emitted += ratio.weight() * mp.sigma_a * mp.emission / mu;
            if (rng.uniform() * mu < st[c]) {
                ratio.take(mp.sigma_s, st);
                sigma_t = st;
                t_out = t;
                scattered = true;
                return false;
            }
            const glm::vec3 sn = glm::max(glm::vec3(mu) - st, glm::vec3(0.0f));
            ratio.take(sn, sn);
        }
    });
    return scattered;
}

}  // namespace

FlightEnd fly(const SceneMedia& media, const Accel& accel, collision::Ray ray, std::int32_t medium, bool moving,
              float time, Rng& rng, std::uint64_t& rays, bool emission) {
    FlightEnd out;
    FlightRatio ratio;
    const int c = std::min(2, static_cast<int>(rng.uniform() * 3.0f));
    for (;;) {
        SurfaceHit hit;
        const bool found = moving ? accel.intersect(ray, time, hit) : accel.intersect(ray, hit);
        if (medium >= 0) {
            const float len = glm::length(ray.dir);
            const glm::vec3 d = ray.dir / len;
            float t = 0.0f;
            const float tmax = found ? hit.t * len : std::numeric_limits<float>::infinity();
            const MediumModel& m = media.model(medium);
            glm::vec3* emitted = emission && m.emits() ? &out.emitted : nullptr;
            if (stretch(m, ray.origin, d, ray.tmin * len, tmax, c, rng, ratio, out.mis_tr, out.sigma_t, t, emitted)) {
                out.kind = FlightEnd::Kind::Medium;
                out.hit = SurfaceHit{};
                out.hit.point = ray.origin + t * d;
                out.hit.object = std::numeric_limits<std::uint32_t>::max();  // no surface (LightSet::kNoObject)
                out.medium = medium;
                out.weight = ratio.weight();
                return out;
            }
        }
        out.medium = medium;
        out.weight = ratio.weight();
        if (!found) return out;  // Escaped (weight 0 through an unbounded medium)
        if (!media.is_interface(hit)) {
            out.kind = FlightEnd::Kind::Surface;
            out.hit = hit;
            return out;
        }
        medium = media.after_crossing(hit.object, hit.normal, ray.dir, medium);
        ray = spawn_ray(hit, ray.dir);
        ++rays;
    }
}

std::int32_t medium_at(const Accel& accel, const Scene& scene, collision::Ray ray, bool moving,
                       float time, std::uint64_t& rays) {
    for (;;) {
        SurfaceHit hit;
        ++rays;
        if (!(moving ? accel.intersect(ray, time, hit) : accel.intersect(ray, hit))) return scene.camera.medium;
        const MediumInterface& mi = scene.objects[hit.object].media;
        if (mi.transition()) return glm::dot(ray.dir, hit.normal) > 0.0f ? mi.inside : mi.outside;
        ray = spawn_ray(hit, ray.dir);
    }
}

}  // namespace sweeptrace

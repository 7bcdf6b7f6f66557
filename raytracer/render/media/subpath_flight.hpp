#pragma once
// Free flights of the bidirectional methods' subpaths (render/integrators/bdpt.cpp, and vcm.cpp
// through it) through the scene's media, and the transmittance of the segments that join them.
//
// A subpath's segment from one vertex to the next is one flight, whatever interface surfaces it
// crosses (they are no vertices, as for the path tracer). Its distance is sampled by one channel c
// chosen uniformly for the whole segment, so the density of the flight's end is the mixture over
// the channels (spectral MIS, as tracking.hpp's hero channel, here per segment):
//   a medium vertex at x:   p(x) = (1/3) sum_c sigma_t,c(x) T_c(segment)   (per unit length)
//   the surface behind:     P    = (1/3) sum_c T_c(segment)                  (a probability)
// and the throughput takes f / p: sigma_s(x) T(segment) / p(x), or T(segment) / P. In homogeneous
// media the distance is drawn in closed form and these are the exact densities. The MIS weights
// of bdpt and vcm count the same p and P (flight_density below) in both directions, so their
// recursive quantities stay exact.
//
// Grids. Delta tracking with channel c against the majorant samples a collision with density
// sigma_t,c(x) T_c, but the mixture needs the other channels' T at the same point, which has no
// closed form; the throughput then takes the sequence-level ratio instead: the density each
// channel's tracking would have given the same tentative collisions (null ones by
// mu - sigma_t,c, the real one by sigma_t,c), which is unbiased for any sequence (Miller,
// Georgiev, Jarosz 2019). In the MIS weights a grid's stretch counts T = 1 (mis_tr): the weights
// need not use the true densities to be unbiased, only to sum to 1 over the strategies of each
// path, and a deterministic function of the path's points, the same from either subpath and in
// every strategy (sigma_t at the vertex, the homogeneous stretches' closed forms), does.
//
// Emission. A camera subpath's flight also estimates the radiance the media along it emit, the
// integral of T sigma_a Le, with the same flight's samples: in a homogeneous stretch at the point
// it scatters, T sigma_a Le / p(x) (the mixture p above); in a grid at every tentative collision,
// sigma_a Le / mu times the sequence-level ratio so far (as tracking.hpp's path tracer collects it,
// pbrt-v4's volpath's collision estimator). The flight's own choices are the only strategy that
// finds such a path (no light subpath and no light sample starts in a medium), so its MIS weight
// is 1 (render/media/README.md).
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "collision/ray.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/render/media/scene_media.hpp"
#include "raytracer/render/media/tracking.hpp"
#include "raytracer/render/sampling/random.hpp"

namespace sweeptrace {

struct FlightEnd {
    enum class Kind : std::uint8_t { Escaped, Surface, Medium };
    Kind kind = Kind::Escaped;
    SurfaceHit hit;            // Surface: the hit; Medium: the point, its error 0
    std::int32_t medium = -1;  // the medium the flight ended in (for a surface, the side it arrived from)
    glm::vec3 weight{1.0f};    // f / p of the flight: the throughput's factor
    glm::vec3 mis_tr{1.0f};    // the transmittance the MIS densities count (closed forms; 1 over grids)
    glm::vec3 sigma_t{0.0f};   // Medium: the extinction at the point
    glm::vec3 emitted{0.0f};   // with `emission`: the media's emission on the way, per unit throughput before the flight
};

// The flight of the ray `ray` (any direction length) starting in `medium` (-1 vacuum), through
// interface surfaces, to the next medium vertex, surface or escape. `rays` counts the rays traced.
// `emission` (camera subpaths): estimate the emission of the media on the way (above).
FlightEnd fly(const SceneMedia& media, const Accel& accel, collision::Ray ray, std::int32_t medium, bool moving,
              float time, Rng& rng, std::uint64_t& rays, bool emission);

// The density factor of a flight's end (above): p for a medium vertex with extinction sigma_t,
// P for a surface, from the segment's MIS transmittance. 1 in vacuum.
inline float flight_density(const glm::vec3& mis_tr, const glm::vec3& sigma_t, bool medium_vertex) {
    return medium_vertex ? mean_of_channels(sigma_t * mis_tr) : mean_of_channels(mis_tr);
}

struct SegmentTransmittance {
    glm::vec3 tr{1.0f};      // the estimate (closed form for homogeneous media, ratio tracking for grids); 0 blocked
    glm::vec3 mis_tr{1.0f};  // what the MIS densities count (as FlightEnd::mis_tr)
};

// The transmittance of the connecting ray `ray` (any direction length, over [tmin, tmax])
// starting in `medium`, through interface surfaces (zero at any other surface); after an
// interface the ray goes on by `next(hit)`, which builds the ray from that hit to the same end.
template <class Next>
SegmentTransmittance segment_transmittance(const SceneMedia& media, const Accel& accel, collision::Ray ray,
                                           std::int32_t medium, bool moving, float time, Rng& rng, std::uint64_t& rays,
                                           Next&& next) {
    SegmentTransmittance out;
    for (;;) {
        SurfaceHit hit;
        const bool found = moving ? accel.intersect(ray, time, hit) : accel.intersect(ray, hit);
        if (found && !media.is_interface(hit)) return {glm::vec3(0.0f), out.mis_tr};
        if (medium >= 0) {
            const float len = glm::length(ray.dir);
            const MediumModel& m = media.model(medium);
            const glm::vec3 tr = transmittance(m, ray.origin, ray.dir / len, ray.tmin * len, (found ? hit.t : ray.tmax) * len, rng);
            out.tr *= tr;
            if (m.homogeneous()) out.mis_tr *= tr;
            if (out.tr == glm::vec3(0.0f)) return out;
        }
        if (!found) return out;
        medium = media.after_crossing(hit.object, hit.normal, ray.dir, medium);
        ray = next(hit);
        ++rays;
    }
}

// The medium a point with no medium of its own is in (a light that is no boundary, a point
// light): found by the first boundary a ray from it along `dir` meets (inside it when the ray
// leaves through its outward side), past interfaces and other surfaces; with no boundary on the
// way, the camera's medium, the one without boundaries.
std::int32_t medium_at(const Accel& accel, const Scene& scene, collision::Ray ray, bool moving,
                       float time, std::uint64_t& rays);

}  // namespace sweeptrace

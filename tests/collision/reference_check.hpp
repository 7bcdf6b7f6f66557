#pragma once
// Judging a float ray-shape answer against the long double reference (reference_intersect.hpp).
//
// A float routine may legitimately differ from the exact answer only where its stated error
// bound makes the exact answer undecidable:
//  - hit vs miss, when the reference line is within `margin_tol` of the classification
//    boundary (reference `margin`);
//  - which crossing is "first", when a crossing lies within its t bound of tmin or tmax.
// Everything else must agree: a hit's t within its bound of the reference crossing it claims,
// and no crossing certainly inside (tmin, tmax) skipped.
#include <functional>
#include <sstream>
#include <string>

#include "collision/finite.hpp"
#include "collision/float_error.hpp"
#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "reference_intersect.hpp"

namespace reference {

struct Verdict {
    bool ok = true;
    const Crossing* matched = nullptr;  // the reference crossing the float hit corresponds to
    std::string why;
};

// `t_bound(c)` is the stated absolute bound on t for the crossing c.
inline Verdict judge(bool got, const collision::RayHit& hit, const Crossings& ref, Real tmin, Real tmax,
                     const std::function<Real(const Crossing&)>& t_bound, Real margin_tol) {
    Verdict v;
    const bool ambiguous = ref.margin <= margin_tol;
    bool earlier_certain = false;
    for (const Crossing& c : ref.hits) {
        const Real tb = t_bound(c);
        const bool possible = c.t > tmin - tb && c.t < tmax + tb;
        const bool certain = c.t > tmin + tb && c.t < tmax - tb;
        if (!possible) continue;
        if (got && !earlier_certain && std::fabs(Real(hit.t) - c.t) <= tb) {
            v.matched = &c;
            return v;
        }
        if (certain) {
            earlier_certain = true;
            break;
        }
    }
    if (!got && !earlier_certain) return v;
    if (ambiguous) {
        // Near the hit/miss boundary the float answer may differ (and a float hit may have no
        // exact counterpart at all).
        if (!got || ref.hits.empty()) return v;
    }
    std::ostringstream s;
    s.precision(10);
    s << (got ? "hit t=" : "miss") << (got ? std::to_string(hit.t) : std::string()) << "; reference:";
    for (const Crossing& c : ref.hits) s << " t=" << double(c.t) << " (bound " << double(t_bound(c)) << ")";
    s << "; margin " << double(ref.margin) << " tol " << double(margin_tol) << "; range (" << double(tmin) << ", "
      << double(tmax) << ")";
    v.ok = false;
    v.why = s.str();
    return v;
}

// Everything a ray test checks of one answer, against the reference:
//  - the verdict of judge();
//  - a hit is finite, its normal unit to gamma(8);
//  - the point lies within its stated per-axis error of the surface: surface_distance(point)
//    (exact, supplied per shape) <= |point_error|;
//  - along the surface the point is as good as t: within (1 + k)(t_bound |d| + gamma(3) (|o| +
//    |t d|)) + |point_error| of the exact crossing o + t d (the rounding of o + t d, and the
//    re-projection, which moves the point by at most k = reprojection_factor times its
//    distance from the surface);
//  - the normal within normal_tol(crossing, that distance) of the exact one.
// Returns "" or a description of the first failure.
struct ShapeChecks {
    std::function<Real(const Crossing&)> t_bound;
    Real margin_tol = 0;
    std::function<Real(const vec3l&)> surface_distance;
    std::function<Real(const Crossing&, Real point_distance)> normal_tol;
    // Re-projection that is not a nearest-point projection can move the point further than its
    // distance from the surface (the ellipsoid's radial one in scaled space: by max/min radius).
    Real reprojection_factor = 1;
};

inline std::string check_answer(const collision::Ray& ray, bool got, const collision::RayHit& hit,
                                const Crossings& ref, const ShapeChecks& sc) {
    const Verdict v = judge(got, hit, ref, ray.tmin, ray.tmax, sc.t_bound, sc.margin_tol);
    if (!v.ok) return v.why;
    if (!got) return "";
    std::ostringstream s;
    s.precision(10);
    using collision::finite;
    if (!std::isfinite(hit.t) || !finite(hit.point) || !finite(hit.point_error) || !finite(hit.normal) ||
        !std::isfinite(hit.uv.x) || !std::isfinite(hit.uv.y))
        return "non-finite hit";
    const Real n_len = glm::length(widen(hit.normal));
    if (std::fabs(n_len - 1) > Real(collision::gamma(8))) {
        s << "normal not unit: " << double(n_len);
        return s.str();
    }
    const Real err = glm::length(widen(hit.point_error));
    const Real dist = sc.surface_distance(widen(hit.point));
    if (!(dist <= err)) {
        s << "point off the surface by " << double(dist) << " > stated " << double(err);
        return s.str();
    }
    if (v.matched == nullptr) return "";
    const vec3l o = widen(ray.origin), d = widen(ray.dir);
    const Real dl = glm::length(d), tb = sc.t_bound(*v.matched);
    const Real along = (1 + sc.reprojection_factor) *
                           (tb * dl + Real(collision::gamma(3)) * (glm::length(o) + std::fabs(v.matched->t) * dl)) +
                       err;
    const Real off = glm::length(widen(hit.point) - (o + v.matched->t * d));
    if (!(off <= along)) {
        s << "point " << double(off) << " from the exact crossing > " << double(along);
        return s.str();
    }
    const Real n_off = glm::length(widen(hit.normal) - v.matched->normal);
    const Real n_tol = sc.normal_tol(*v.matched, along);
    if (!(n_off <= n_tol)) {
        s << "normal off by " << double(n_off) << " > " << double(n_tol) << " at t=" << double(v.matched->t);
        return s.str();
    }
    return "";
}

}  // namespace reference

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

#include "collision/hit.hpp"
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

}  // namespace reference

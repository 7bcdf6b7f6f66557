#pragma once
// The accuracy reference: every ray-shape routine of collision/ redone in long double, with the
// hit/miss decision made three-valued. A case whose decision lies within the reference's own
// rounding band is `Boundary` (the exact ray touches an edge, a silhouette or the ray's start):
// there either answer is right, so it is left out of the wrong hit/miss count and counted apart.
//
// Why long double is enough. Every input is a float, so differences of inputs are exact in long
// double (64-bit significand) whenever their exponents differ by less than 40, which holds for
// every case generated here (coordinates 1e-4 .. 1e6). Each decision below is a handful of
// products and sums, so its rounding error is under 2^-58 of the magnitudes it combines. The band
// is set at 2^-46 of those magnitudes: 4096 times the worst rounding error (so the reference never
// decides a case its arithmetic cannot), and still 2^22 (4 million) times smaller than one float
// ulp (2^-24), so every case a float routine could possibly get right is decided.
#include <glm/vec3.hpp>

#include "collision/ray.hpp"
#include "collision/shapes.hpp"

namespace sweeptrace::accuracy {

using LVec3 = glm::vec<3, long double, glm::defaultp>;

inline LVec3 widen(const glm::vec3& v) { return LVec3(v.x, v.y, v.z); }

// Relative size of the undecidable band (see above).
inline constexpr long double reference_band = 1.0L / 70368744177664.0L;  // 2^-46

// A wider band at float resolution: 2^-16 = 256 float ulps of the same magnitudes. The robust
// routines state error bounds of gamma(n) with n <= 32 (2^-19); a case still decided with this
// band is one a float routine within its bound must get right, so a wrong answer there is a
// defect, not rounding. Cases inside it are "within rounding": any answer is defensible.
inline constexpr long double float_band = 1.0L / 65536.0L;  // 2^-16

struct LRay {
    LVec3 origin;
    LVec3 dir;
    long double tmin = 0.0L;
    long double tmax = 0.0L;
    long double band = reference_band;  // relative band of the decisions on this ray
};

inline LRay widen(const collision::Ray& r, long double band = reference_band) {
    return LRay{widen(r.origin), widen(r.dir), r.tmin, r.tmax, band};
}

// Where the ray's *line* meets the shape: the parameter interval [t0, t1] inside a closed shape,
// or t0 == t1 for a flat one, with the outward normals there. `ambiguous` is set when whether the
// line meets the shape at all lies within the band (tangent, through an edge or a rim).
struct RefSpan {
    bool meets = false;
    bool ambiguous = false;
    long double t0 = 0.0L, t1 = 0.0L;
    LVec3 n0{0.0L}, n1{0.0L};
    long double band_t = 0.0L;  // absolute band on t0 / t1 (comparisons with tmin, tmax)
};

RefSpan reference_span(const LRay& ray, const collision::Sphere& s);
RefSpan reference_span(const LRay& ray, const collision::Aabb& b);
RefSpan reference_span(const LRay& ray, const collision::Cylinder& c);
RefSpan reference_span(const LRay& ray, const collision::Capsule& c);
RefSpan reference_span(const LRay& ray, const collision::OrientedCapsule& c);
RefSpan reference_span(const LRay& ray, const collision::Ellipsoid& e);
RefSpan reference_span(const LRay& ray, const collision::Plane& p);
RefSpan reference_span(const LRay& ray, const collision::Disk& d);
RefSpan reference_span(const LRay& ray, const collision::Quad& q);
RefSpan reference_span(const LRay& ray, const collision::Triangle& t);

enum class RefOutcome { Miss, Hit, Boundary };

struct RefHit {
    RefOutcome outcome = RefOutcome::Miss;
    long double t = 0.0L;
    LVec3 normal{0.0L};
};

// The routines' contract applied to the span: nearest t with tmin < t < tmax (the exit when the
// ray starts inside); Boundary when that choice depends on a value within the band.
RefHit nearest(const RefSpan& span, long double tmin, long double tmax);

template <class Shape>
RefHit reference(const collision::Ray& ray, const Shape& shape, long double band = reference_band) {
    const LRay r = widen(ray, band);
    return nearest(reference_span(r, shape), r.tmin, r.tmax);
}

}  // namespace sweeptrace::accuracy

// The two long double ray-shape references must give the same answers on the same cases.
//
// They stay apart because they answer different questions: tests/collision/reference_intersect.hpp
// returns every crossing of the ray's *line* with the margin to the nearest hit/miss change and
// the parts (side, cap, sphere) the unit tests need to apply each intersector's stated bound;
// raytracer/accuracy/reference.hpp decides each ray three-valued (hit, miss, or Boundary within
// its 2^-46 band), which is what the published accuracy tables count. Both are long double
// computations of the same exact geometry, so wherever the accuracy reference decides a case
// beyond its band, the test reference must agree: same hit/miss, the same t within the accuracy
// reference's absolute band on t, the same outward normal. Cases: every ray family of
// `sweeptrace accuracy` (cases.hpp) for every shape.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "../collision/reference_intersect.hpp"
#include "raytracer/accuracy/cases.hpp"
#include "raytracer/accuracy/reference.hpp"

namespace acc = sweeptrace::accuracy;
namespace ref = reference;

namespace {

using ref::Crossings;
using ref::vec3l;
using ref::widen;

Crossings crossings(const vec3l& o, const vec3l& d, const collision::Sphere& s) {
    return ref::sphere(o, d, widen(s.center), s.radius);
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::Aabb& b) {
    return ref::box(o, d, widen(b.center), widen(b.size));
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::Cylinder& c) {
    return ref::cylinder(o, d, widen(c.center), c.radius, c.height);
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::Capsule& c) {
    const vec3l half(0.0L, 0.5L * c.height, 0.0L);
    return ref::capsule(o, d, widen(c.center) - half, widen(c.center) + half, c.radius);
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::OrientedCapsule& c) {
    return ref::capsule(o, d, widen(c.a), widen(c.b), c.radius);
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::Ellipsoid& e) {
    return ref::ellipsoid(o, d, widen(e.center), widen(e.radii));
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::Plane& p) {
    return ref::plane(o, d, widen(p.point), widen(p.normal));
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::Disk& k) {
    return ref::disk(o, d, widen(k.center), widen(k.normal), k.radius);
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::Quad& q) {
    return ref::quad(o, d, widen(q.corner), widen(q.edge_u), widen(q.edge_v));
}
Crossings crossings(const vec3l& o, const vec3l& d, const collision::Triangle& t) {
    return ref::triangle(o, d, widen(t.a), widen(t.b), widen(t.c));
}

struct CaseCounts {
    int decided = 0, boundary = 0, hits = 0;
};

// One case: "" when the references agree (or the accuracy reference calls it Boundary), else why.
template <class S>
std::string compare(const acc::Case<S>& c, CaseCounts& counts) {
    const acc::RefSpan span = acc::reference_span(acc::widen(c.ray), c.shape);
    const acc::RefHit a = acc::nearest(span, c.ray.tmin, c.ray.tmax);
    if (a.outcome == acc::RefOutcome::Boundary) {
        ++counts.boundary;
        return "";
    }
    ++counts.decided;
    const Crossings x = crossings(widen(c.ray.origin), widen(c.ray.dir), c.shape);
    const ref::Crossing* first = nullptr;
    for (const ref::Crossing& h : x.hits) {
        if (h.t > c.ray.tmin && h.t < c.ray.tmax) {
            first = &h;
            break;
        }
    }
    const bool hit = a.outcome == acc::RefOutcome::Hit;
    if (hit != (first != nullptr))
        return std::string("accuracy reference says ") + (hit ? "hit" : "miss") + ", test reference " +
               (first ? "hit" : "miss");
    if (!hit) return "";
    ++counts.hits;
    const long double dt = std::fabs(first->t - a.t);
    if (!(dt <= span.band_t))
        return "t " + std::to_string(double(first->t)) + " vs " + std::to_string(double(a.t)) + ", band " +
               std::to_string(double(span.band_t));
    // Both normals are unit (to long double rounding); 2^-40 is far above that rounding and far
    // below any float answer's error, so it separates agreement from a different face.
    const long double dn = glm::length(first->normal - a.normal);
    if (!(dn <= 1.0L / 1099511627776.0L)) return "normals differ by " + std::to_string(double(dn));
    return "";
}

template <class S>
void agree_on_every_family() {
    for (const acc::Family f : acc::all_families) {
        if (f == acc::Family::Edges || !acc::family_applies<S>(f)) continue;
        CaseCounts counts;
        int disagreements = 0;
        for (const auto& c : acc::make_cases<S>(f, 2000, 11)) {
            const std::string why = compare(c, counts);
            if (why.empty()) continue;
            if (++disagreements <= 3) {
                INFO(acc::shape_name<S>() << " / " << acc::family_name(f) << ": " << why);
                CHECK(why.empty());
            }
        }
        INFO(acc::shape_name<S>() << " / " << acc::family_name(f) << ": " << disagreements << " of " << counts.decided
                                  << " decided cases disagree (" << counts.boundary << " Boundary)");
        CHECK(disagreements == 0);
        // The comparison must have had something to compare.
        CHECK(counts.decided > 1000);
    }
}

}  // namespace

TEST_CASE("references agree: the test reference and the accuracy reference on the accuracy families",
          "[stability][reference]") {
    agree_on_every_family<collision::Sphere>();
    agree_on_every_family<collision::Aabb>();
    agree_on_every_family<collision::Cylinder>();
    agree_on_every_family<collision::Capsule>();
    agree_on_every_family<collision::OrientedCapsule>();
    agree_on_every_family<collision::Ellipsoid>();
    agree_on_every_family<collision::Plane>();
    agree_on_every_family<collision::Disk>();
    agree_on_every_family<collision::Quad>();
    agree_on_every_family<collision::Triangle>();
}

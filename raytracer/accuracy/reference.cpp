// Long double reference intersections; the band argument is in reference.hpp. Every helper
// takes the relative band (the ray carries it) so the same code also answers "is this case
// decided beyond float rounding?" with float_band.
#include "raytracer/accuracy/reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace sweeptrace::accuracy {
namespace {

constexpr long double inf = std::numeric_limits<long double>::infinity();

long double norm(const LVec3& v) { return std::sqrt(glm::dot(v, v)); }
LVec3 unit(const LVec3& v) {
    const long double n = norm(v);
    return n > 0.0L ? v / n : LVec3(0.0L);
}
long double det(const LVec3& a, const LVec3& b, const LVec3& c) { return glm::dot(glm::cross(a, b), c); }

// Component-wise magnitudes for rounding bounds (Higham: |fl(x.y) - x.y| <= gamma_n |x|.|y|).
long double abs_dot(const LVec3& a, const LVec3& b) {
    return std::fabs(a.x * b.x) + std::fabs(a.y * b.y) + std::fabs(a.z * b.z);
}
long double abs_det(const LVec3& a, const LVec3& b, const LVec3& c) {
    const LVec3 m(std::fabs(a.y * b.z) + std::fabs(a.z * b.y), std::fabs(a.z * b.x) + std::fabs(a.x * b.z),
                  std::fabs(a.x * b.y) + std::fabs(a.y * b.x));
    return abs_dot(m, c);
}

// Where the line f + t d (f = origin relative to the centre) meets the ball of radius r:
// closest-approach form, so the discriminant does not cancel for far origins.
RefSpan ball_span(const LVec3& f, const LVec3& d, long double r, long double band) {
    RefSpan s;
    const long double a = glm::dot(d, d);
    if (!(a > 0.0L) || !(r > 0.0L)) return s;
    const long double b = glm::dot(f, d);
    const LVec3 l = f - (b / a) * d;  // closest approach of the line to the centre
    const long double h = r * r - glm::dot(l, l);
    const long double scale = r * r + norm(l) * norm(f) + glm::dot(l, l);
    s.ambiguous = std::fabs(h) <= band * scale;
    s.band_t = band * (norm(f) + r) / std::sqrt(a);
    if (h < 0.0L) return s;
    const long double root = std::sqrt(a * h);
    const long double q = -(b + std::copysign(root, b));
    const long double c = glm::dot(f, f) - r * r;
    long double t0 = q / a, t1 = q != 0.0L ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    s.meets = true;
    s.t0 = t0;
    s.t1 = t1;
    s.n0 = unit(f + t0 * d);
    s.n1 = unit(f + t1 * d);
    return s;
}

// Intersection of two spans of one convex shape (e.g. infinite cylinder and slab).
RefSpan intersect_spans(const RefSpan& x, const RefSpan& y, long double band) {
    RefSpan s;
    s.band_t = std::max(x.band_t, y.band_t);
    if (!x.meets || !y.meets) {
        // A part missed decisively settles it; otherwise the missing part was within the band.
        s.ambiguous = (x.meets || x.ambiguous) && (y.meets || y.ambiguous);
        return s;
    }
    const bool x_enters = x.t0 >= y.t0;
    s.t0 = x_enters ? x.t0 : y.t0;
    s.n0 = x_enters ? x.n0 : y.n0;
    const bool x_exits = x.t1 <= y.t1;
    s.t1 = x_exits ? x.t1 : y.t1;
    s.n1 = x_exits ? x.n1 : y.n1;
    const long double gap = s.t1 - s.t0;
    s.meets = gap >= 0.0L;
    // Touching an edge or a rim: entry and exit coincide within the band.
    bool edge = false;
    if (std::isfinite(gap)) {
        const long double scale = std::max(std::fabs(s.t0), std::fabs(s.t1));
        edge = std::fabs(gap) <= band * scale + s.band_t;
    }
    // An ambiguous part (a ray lying exactly in a face plane or along a cylinder wall, or an
    // earlier edge) keeps the result ambiguous unless the other part excludes it decisively.
    s.ambiguous = edge || ((x.ambiguous || y.ambiguous) && s.meets);
    return s;
}

// Union of the spans of convex parts whose union is convex (capsule = cylinder + two balls).
RefSpan unite_spans(const RefSpan* parts, int n) {
    RefSpan s;
    bool any_ambiguous = false;
    for (int i = 0; i < n; ++i) {
        const RefSpan& p = parts[i];
        s.band_t = std::max(s.band_t, p.band_t);
        any_ambiguous = any_ambiguous || p.ambiguous;
        if (!p.meets) continue;
        if (!s.meets || p.t0 < s.t0) { s.t0 = p.t0; s.n0 = p.n0; }
        if (!s.meets || p.t1 > s.t1) { s.t1 = p.t1; s.n1 = p.n1; }
        s.meets = true;
    }
    // Decided when some part is met decisively (its own tangency and edges are in its flag);
    // ambiguous when every part met, or (if none is met) some part missed, within the band.
    bool all_met_ambiguous = true;
    for (int i = 0; i < n; ++i) {
        if (parts[i].meets && !parts[i].ambiguous) all_met_ambiguous = false;
    }
    s.ambiguous = s.meets ? all_met_ambiguous : any_ambiguous;
    return s;
}

// The slab lo <= x(t) <= hi along one coordinate x(t) = f + t g (g = direction along the axis).
// `magnitude` is the size of the coordinates f was computed from (the band is relative to it).
RefSpan slab_span(long double f, long double g, long double lo, long double hi, const LVec3& axis, long double band,
                  long double magnitude) {
    RefSpan s;
    if (g == 0.0L) {
        // Parallel to the slab's planes: all of the line or none of it; exactly in a plane is
        // the grazing-a-face case, ambiguous.
        s.ambiguous = std::fabs(f - lo) <= band * magnitude || std::fabs(f - hi) <= band * magnitude;
        if (f >= lo && f <= hi) {
            s.meets = true;
            s.t0 = -inf;
            s.t1 = inf;
        }
        return s;
    }
    long double ta = (lo - f) / g, tb = (hi - f) / g;
    if (ta > tb) std::swap(ta, tb);
    s.meets = true;
    s.t0 = ta;
    s.t1 = tb;
    s.n0 = g > 0.0L ? -axis : axis;
    s.n1 = -s.n0;
    s.band_t = band * (std::fabs(ta) + std::fabs(tb));
    return s;
}

// Solid cylinder from `a` along unit `u` over [0, len], radius r.
RefSpan cylinder_span(const LRay& ray, const LVec3& a, const LVec3& u, long double len, long double r) {
    const LVec3 f = ray.origin - a;
    const long double fu = glm::dot(f, u), du = glm::dot(ray.dir, u);
    const LVec3 f_perp = f - fu * u;
    const LVec3 d_perp = ray.dir - du * u;
    RefSpan side;
    if (glm::dot(d_perp, d_perp) > 0.0L) {
        side = ball_span(f_perp, d_perp, r, ray.band);
    } else {
        // Along the axis: inside the infinite cylinder for every t, or never.
        const long double dist2 = glm::dot(f_perp, f_perp);
        side.ambiguous = std::fabs(dist2 - r * r) <= ray.band * (r * r + dist2);
        if (dist2 <= r * r) {
            side.meets = true;
            side.t0 = -inf;
            side.t1 = inf;
        }
    }
    const RefSpan caps = slab_span(fu, du, 0.0L, len, u, ray.band, std::fabs(glm::dot(ray.origin, u)) + std::fabs(glm::dot(a, u)) + len);
    RefSpan s = intersect_spans(side, caps, ray.band);
    s.band_t = std::max(s.band_t, ray.band * (norm(f) + r + len) / norm(ray.dir));
    return s;
}

RefSpan capsule_span(const LRay& ray, const LVec3& a, const LVec3& b, long double r) {
    const LVec3 axis = b - a;
    const long double len = norm(axis);
    if (!(len > 0.0L)) return ball_span(ray.origin - a, ray.dir, r, ray.band);
    const RefSpan parts[3] = {cylinder_span(ray, a, axis / len, len, r), ball_span(ray.origin - a, ray.dir, r, ray.band),
                              ball_span(ray.origin - b, ray.dir, r, ray.band)};
    return unite_spans(parts, 3);
}

// Flat convex polygon: the line crosses its interior when the signed volumes of every edge with
// the ray direction agree in sign. The shared edge of two triangles gives the same volume with
// opposite sign in both, so this reference is watertight by construction.
RefSpan polygon_span(const LRay& ray, const LVec3* corners, int n, const LVec3& normal) {
    RefSpan s;
    const long double nd = glm::dot(normal, ray.dir);
    const long double num = glm::dot(normal, corners[0] - ray.origin);
    if (nd == 0.0L) {
        s.ambiguous = std::fabs(num) <= ray.band * abs_dot(normal, corners[0] - ray.origin);
        return s;
    }
    bool positive = false, negative = false, near_zero = false;
    for (int i = 0; i < n; ++i) {
        const LVec3 p = corners[i] - ray.origin, q = corners[(i + 1) % n] - ray.origin;
        const long double w = det(p, q, ray.dir);
        if (std::fabs(w) <= ray.band * abs_det(p, q, ray.dir)) near_zero = true;
        else if (w > 0.0L) positive = true;
        else negative = true;
    }
    const long double t = num / nd;
    s.band_t = ray.band * std::fabs(t) *
               (norm(normal) * norm(corners[0] - ray.origin) / std::max(std::fabs(num), std::numeric_limits<long double>::min()) +
                norm(normal) * norm(ray.dir) / std::fabs(nd));
    if (positive && negative) return s;  // decisively outside one edge
    s.ambiguous = near_zero;
    s.meets = true;
    s.t0 = s.t1 = t;
    s.n0 = s.n1 = unit(normal);
    return s;
}

}  // namespace

RefSpan reference_span(const LRay& ray, const collision::Sphere& s) {
    return ball_span(ray.origin - widen(s.center), ray.dir, s.radius, ray.band);
}

RefSpan reference_span(const LRay& ray, const collision::Aabb& b) {
    RefSpan s;
    if (!(b.size.x > 0.0f && b.size.y > 0.0f && b.size.z > 0.0f) || glm::dot(ray.dir, ray.dir) == 0.0L) return s;
    const LVec3 c = widen(b.center), half = widen(b.size) * 0.5L;
    for (int k = 0; k < 3; ++k) {
        LVec3 axis(0.0L);
        axis[k] = 1.0L;
        const RefSpan slab = slab_span(ray.origin[k], ray.dir[k], c[k] - half[k], c[k] + half[k], axis, ray.band,
                                        std::fabs(ray.origin[k]) + std::fabs(c[k]) + half[k]);
        s = k == 0 ? slab : intersect_spans(s, slab, ray.band);
    }
    return s;
}

RefSpan reference_span(const LRay& ray, const collision::Cylinder& c) {
    if (!(c.radius > 0.0f && c.height > 0.0f) || glm::dot(ray.dir, ray.dir) == 0.0L) return {};
    const LVec3 bottom = widen(c.center) - LVec3(0.0L, 0.5L * c.height, 0.0L);
    return cylinder_span(ray, bottom, LVec3(0.0L, 1.0L, 0.0L), c.height, c.radius);
}

RefSpan reference_span(const LRay& ray, const collision::Capsule& c) {
    if (!(c.radius > 0.0f && c.height >= 0.0f) || glm::dot(ray.dir, ray.dir) == 0.0L) return {};
    const LVec3 half(0.0L, 0.5L * c.height, 0.0L);
    return capsule_span(ray, widen(c.center) - half, widen(c.center) + half, c.radius);
}

RefSpan reference_span(const LRay& ray, const collision::OrientedCapsule& c) {
    if (!(c.radius > 0.0f) || glm::dot(ray.dir, ray.dir) == 0.0L) return {};
    return capsule_span(ray, widen(c.a), widen(c.b), c.radius);
}

RefSpan reference_span(const LRay& ray, const collision::Ellipsoid& e) {
    if (!(e.radii.x > 0.0f && e.radii.y > 0.0f && e.radii.z > 0.0f)) return {};
    const LVec3 radii = widen(e.radii);
    RefSpan s = ball_span((ray.origin - widen(e.center)) / radii, ray.dir / radii, 1.0L, ray.band);
    // Normal of the ellipsoid = gradient (p - c) / radii^2 = (unit-sphere point) / radii.
    s.n0 = unit(s.n0 / radii);
    s.n1 = unit(s.n1 / radii);
    return s;
}

RefSpan reference_span(const LRay& ray, const collision::Plane& p) {
    RefSpan s;
    const LVec3 n = widen(p.normal);
    const long double nd = glm::dot(n, ray.dir);
    const LVec3 to_plane = widen(p.point) - ray.origin;
    const long double num = glm::dot(n, to_plane);
    if (nd == 0.0L || !(glm::dot(n, n) > 0.0L)) {
        s.ambiguous = glm::dot(n, n) > 0.0L && std::fabs(num) <= ray.band * abs_dot(n, to_plane);
        return s;
    }
    const long double t = num / nd;
    s.meets = true;
    s.t0 = s.t1 = t;
    s.n0 = s.n1 = unit(n);
    s.band_t = ray.band * std::fabs(t) * 4.0L *
               (norm(n) * norm(to_plane) / std::max(std::fabs(num), std::numeric_limits<long double>::min()) +
                norm(n) * norm(ray.dir) / std::fabs(nd));
    return s;
}

RefSpan reference_span(const LRay& ray, const collision::Disk& d) {
    if (!(d.radius > 0.0f)) return {};
    RefSpan s = reference_span(ray, collision::Plane{d.center, d.normal});
    if (!s.meets) return s;
    const LVec3 c = widen(d.center);
    const LVec3 p = ray.origin + s.t0 * ray.dir;
    const long double r = d.radius;
    const long double dist2 = glm::dot(p - c, p - c);
    const long double scale = r + norm(ray.origin - c) + std::fabs(s.t0) * norm(ray.dir);
    const bool edge = std::fabs(dist2 - r * r) <= ray.band * scale * scale;
    s.ambiguous = s.ambiguous || edge;
    if (dist2 > r * r) s.meets = false;
    return s;
}

RefSpan reference_span(const LRay& ray, const collision::Quad& q) {
    const LVec3 o = widen(q.corner), u = widen(q.edge_u), v = widen(q.edge_v);
    const LVec3 n = glm::cross(u, v);
    if (!(glm::dot(n, n) > 0.0L)) return {};
    const LVec3 corners[4] = {o, o + u, o + u + v, o + v};
    return polygon_span(ray, corners, 4, n);
}

RefSpan reference_span(const LRay& ray, const collision::Triangle& t) {
    const LVec3 corners[3] = {widen(t.a), widen(t.b), widen(t.c)};
    const LVec3 n = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
    if (!(glm::dot(n, n) > 0.0L)) return {};
    return polygon_span(ray, corners, 3, n);
}

RefHit nearest(const RefSpan& span, long double tmin, long double tmax) {
    RefHit h;
    if (span.ambiguous) {
        h.outcome = RefOutcome::Boundary;
        return h;
    }
    if (!span.meets) return h;
    const long double ts[2] = {span.t0, span.t1};
    const LVec3 ns[2] = {span.n0, span.n1};
    for (int i = 0; i < 2; ++i) {
        const long double t = ts[i];
        if (std::fabs(t - tmin) <= span.band_t) {
            h.outcome = RefOutcome::Boundary;
            return h;
        }
        if (t > tmin) {
            if (std::fabs(t - tmax) <= span.band_t) h.outcome = RefOutcome::Boundary;
            else if (t < tmax) h = RefHit{RefOutcome::Hit, t, ns[i]};
            return h;
        }
    }
    return h;
}

}  // namespace sweeptrace::accuracy

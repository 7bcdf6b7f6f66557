// Ray families. Every random draw comes from one seeded stream per (family, shape), so the same
// seed gives the same cases on every machine and for every variant measured on them.
#include "raytracer/accuracy/cases.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "raytracer/accuracy/reference.hpp"

namespace sweeptrace::accuracy {

using collision::Ray;
using glm::vec3;

const char* family_name(Family f) {
    switch (f) {
        case Family::Uniform: return "uniform";
        case Family::Grazing: return "grazing";
        case Family::Far: return "far";
        case Family::Huge: return "huge";
        case Family::Tiny: return "tiny";
        case Family::SurfaceOut: return "surface-out";
        case Family::SurfaceIn: return "surface-in";
        case Family::Parallel: return "parallel";
        case Family::Edges: return "edges";
    }
    return "?";
}

template <> const char* shape_name<collision::OrientedCapsule>() { return "oriented-capsule"; }
template <> const char* shape_name<collision::Plane>() { return "plane"; }

glm::vec3 offset_origin(const vec3& p, const vec3& error, const vec3& normal, const vec3& dir) {
    const float d = glm::dot(glm::abs(normal), error);
    vec3 offset = d * normal;
    if (glm::dot(dir, normal) < 0.0f) offset = -offset;
    vec3 o = p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) o[i] = std::nextafter(o[i], std::numeric_limits<float>::infinity());
        else if (offset[i] < 0.0f) o[i] = std::nextafter(o[i], -std::numeric_limits<float>::infinity());
    }
    return o;
}

glm::vec3 unit_vector(CaseRng& rng) {
    std::normal_distribution<float> g(0.0f, 1.0f);
    for (;;) {
        const vec3 v(g(rng), g(rng), g(rng));
        const float l = glm::length(v);
        if (l > 1e-3f) return v / l;
    }
}

namespace {

float uniform(CaseRng& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }


vec3 in_ball(CaseRng& rng) { return unit_vector(rng) * std::cbrt(uniform(rng, 0.0f, 1.0f)); }
vec3 in_cube(CaseRng& rng) { return vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)); }

// Shape generators: `s` is the size scale, the shape fits in a ball of about radius s.
collision::Sphere make(CaseRng& rng, float s, vec3 c, collision::Sphere*) { return {c, s * uniform(rng, 0.5f, 1.0f)}; }
collision::Aabb make(CaseRng& rng, float s, vec3 c, collision::Aabb*) {
    return {c, s * vec3(uniform(rng, 0.5f, 1.2f), uniform(rng, 0.5f, 1.2f), uniform(rng, 0.5f, 1.2f))};
}
collision::Cylinder make(CaseRng& rng, float s, vec3 c, collision::Cylinder*) {
    return {c, s * uniform(rng, 0.3f, 0.7f), s * uniform(rng, 0.5f, 1.4f)};
}
collision::Capsule make(CaseRng& rng, float s, vec3 c, collision::Capsule*) {
    return {c, s * uniform(rng, 0.2f, 0.5f), s * uniform(rng, 0.3f, 1.0f)};
}
collision::OrientedCapsule make(CaseRng& rng, float s, vec3 c, collision::OrientedCapsule*) {
    const vec3 half = unit_vector(rng) * (s * uniform(rng, 0.15f, 0.5f));
    return {c - half, c + half, s * uniform(rng, 0.2f, 0.5f)};
}
collision::Ellipsoid make(CaseRng& rng, float s, vec3 c, collision::Ellipsoid*) {
    return {c, s * vec3(uniform(rng, 0.3f, 1.0f), uniform(rng, 0.3f, 1.0f), uniform(rng, 0.3f, 1.0f))};
}
collision::Plane make(CaseRng& rng, float, vec3 c, collision::Plane*) { return {c, unit_vector(rng)}; }
collision::Disk make(CaseRng& rng, float s, vec3 c, collision::Disk*) {
    return {c, unit_vector(rng), s * uniform(rng, 0.5f, 1.0f)};
}
collision::Quad make(CaseRng& rng, float s, vec3 c, collision::Quad*) {
    const vec3 u = unit_vector(rng) * (s * uniform(rng, 0.6f, 1.4f));
    vec3 v = unit_vector(rng) * (s * uniform(rng, 0.6f, 1.4f));
    if (glm::length(glm::cross(u, v)) < 0.1f * glm::length(u) * glm::length(v)) v = glm::cross(u, vec3(0.3f, 1.0f, 0.2f));
    return {c - 0.5f * (u + v), u, v};
}
collision::Triangle make(CaseRng& rng, float s, vec3 c, collision::Triangle*) {
    for (;;) {
        const collision::Triangle t{c + s * in_ball(rng), c + s * in_ball(rng), c + s * in_ball(rng)};
        if (glm::length(glm::cross(t.b - t.a, t.c - t.a)) > 0.05f * s * s) return t;
    }
}

template <class S>
S make_shape(CaseRng& rng, float s, vec3 c) {
    return make(rng, s, c, static_cast<S*>(nullptr));
}

// Where to aim: a point near the shape, in the ball of radius extent around centre.
vec3 centre(const collision::Sphere& s) { return s.center; }
vec3 centre(const collision::Aabb& b) { return b.center; }
vec3 centre(const collision::Cylinder& c) { return c.center; }
vec3 centre(const collision::Capsule& c) { return c.center; }
vec3 centre(const collision::OrientedCapsule& c) { return 0.5f * (c.a + c.b); }
vec3 centre(const collision::Ellipsoid& e) { return e.center; }
vec3 centre(const collision::Plane& p) { return p.point; }
vec3 centre(const collision::Disk& d) { return d.center; }
vec3 centre(const collision::Quad& q) { return q.corner + 0.5f * (q.edge_u + q.edge_v); }
vec3 centre(const collision::Triangle& t) { return (t.a + t.b + t.c) / 3.0f; }

float extent(const collision::Sphere& s) { return s.radius; }
float extent(const collision::Aabb& b) { return 0.5f * glm::length(b.size); }
float extent(const collision::Cylinder& c) { return std::hypot(c.radius, 0.5f * c.height); }
float extent(const collision::Capsule& c) { return c.radius + 0.5f * c.height; }
float extent(const collision::OrientedCapsule& c) { return c.radius + 0.5f * glm::length(c.b - c.a); }
float extent(const collision::Ellipsoid& e) { return std::max(e.radii.x, std::max(e.radii.y, e.radii.z)); }
float extent(const collision::Plane&) { return 1.0f; }
float extent(const collision::Disk& d) { return d.radius; }
float extent(const collision::Quad& q) { return 0.5f * (glm::length(q.edge_u) + glm::length(q.edge_v)); }
float extent(const collision::Triangle& t) {
    const vec3 c = centre(t);
    return std::max(glm::length(t.a - c), std::max(glm::length(t.b - c), glm::length(t.c - c)));
}

// A ray from `distance` away from the shape aimed at a point of its bounding ball.
template <class S>
Ray aimed_ray(CaseRng& rng, const S& shape, float distance, float extent_scale = 1.0f) {
    const vec3 c = centre(shape);
    const float e = extent(shape) * extent_scale;
    const vec3 origin = c + unit_vector(rng) * distance;
    const vec3 target = c + e * in_ball(rng);
    return Ray{origin, glm::normalize(target - origin)};
}

template <class S>
constexpr bool is_flat() {
    return std::is_same_v<S, collision::Plane> || std::is_same_v<S, collision::Disk> ||
           std::is_same_v<S, collision::Quad> || std::is_same_v<S, collision::Triangle>;
}

// Grazing: a reference surface point, a tangent there, and an origin k ulps off the tangent line.
template <class S>
bool grazing_case(CaseRng& rng, Case<S>& out) {
    const S shape = make_shape<S>(rng, 1.0f, in_cube(rng));
    for (int attempt = 0; attempt < 16; ++attempt) {
        const Ray probe = aimed_ray(rng, shape, 4.0f * extent(shape), 0.8f);
        const RefSpan span = reference_span(widen(probe), shape);
        if (!span.meets || span.ambiguous) continue;
        const LVec3 p = widen(probe.origin) + span.t0 * widen(probe.dir);
        const LVec3 n = span.n0;
        LVec3 tangent = glm::cross(n, widen(unit_vector(rng)));
        const long double tl = std::sqrt(glm::dot(tangent, tangent));
        if (!(tl > 1e-3L)) continue;
        tangent /= tl;
        const long double length = 3.0L * extent(shape);
        LVec3 origin = p - length * tangent;
        const float biggest = std::max(std::fabs(float(origin.x)), std::max(std::fabs(float(origin.y)), std::fabs(float(origin.z))));
        const float ulp = std::nextafter(biggest, std::numeric_limits<float>::infinity()) - biggest;
        const int k = std::uniform_int_distribution<int>(-4, 4)(rng);
        origin += n * (static_cast<long double>(k) * ulp);
        out.shape = shape;
        out.ray = Ray{vec3(float(origin.x), float(origin.y), float(origin.z)),
                      vec3(float(tangent.x), float(tangent.y), float(tangent.z))};
        return true;
    }
    return false;
}

// One float ulp of v, toward +inf or -inf.
float nudge(float v, int steps) {
    const float to = steps > 0 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
    for (int i = 0; i < std::abs(steps); ++i) v = std::nextafter(v, to);
    return v;
}

// A coordinate exactly on a plane at `at`, an ulp or two off it, or clearly inside / outside.
float plane_coordinate(CaseRng& rng, float at, float inside_dir, float size) {
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
        case 0: return at;
        case 1: return nudge(at, std::uniform_int_distribution<int>(-2, 2)(rng));
        case 2: return at + inside_dir * size * uniform(rng, 0.01f, 0.9f);
        case 3: return at - inside_dir * size * uniform(rng, 0.01f, 0.9f);
        default: return nudge(at, 1);
    }
}

// Direction in the plane perpendicular to `axis` (an exact zero component).
vec3 flat_direction(CaseRng& rng, int axis) {
    vec3 d = unit_vector(rng);
    d[axis] = 0.0f;
    if (glm::length(d) < 1e-3f) d[(axis + 1) % 3] = 1.0f;
    return glm::normalize(d);
}

// Parallel cases: `false` when the shape has nothing to be parallel to.
bool parallel_case(CaseRng&, Case<collision::Sphere>&) { return false; }
bool parallel_case(CaseRng&, Case<collision::Ellipsoid>&) { return false; }
bool parallel_case(CaseRng& rng, Case<collision::Aabb>& out) {
    const collision::Aabb b = make_shape<collision::Aabb>(rng, 1.0f, in_cube(rng));
    const int axis = std::uniform_int_distribution<int>(0, 2)(rng);
    vec3 d = flat_direction(rng, axis);
    if (uniform(rng, 0, 1) < 0.3f) {  // parallel to two faces: along one axis only
        d = vec3(0.0f);
        d[(axis + 1) % 3] = uniform(rng, 0, 1) < 0.5f ? 1.0f : -1.0f;
    }
    const bool top = uniform(rng, 0, 1) < 0.5f;
    const float plane = top ? b.max()[axis] : b.min()[axis];
    vec3 o = b.center - d * (3.0f * extent(b)) + 0.5f * b.size * in_cube(rng) * (vec3(1.0f) - glm::abs(d));
    o[axis] = plane_coordinate(rng, plane, top ? -1.0f : 1.0f, b.size[axis]);
    out.shape = b;
    out.ray = Ray{o, d};
    return true;
}
bool parallel_case(CaseRng& rng, Case<collision::Cylinder>& out) {
    const collision::Cylinder c = make_shape<collision::Cylinder>(rng, 1.0f, in_cube(rng));
    out.shape = c;
    if (uniform(rng, 0, 1) < 0.5f) {  // parallel to the caps
        const vec3 d = flat_direction(rng, 1);
        const bool top = uniform(rng, 0, 1) < 0.5f;
        vec3 o = c.center - d * (3.0f * extent(c)) + glm::cross(d, vec3(0, 1, 0)) * (c.radius * uniform(rng, -1.2f, 1.2f));
        o.y = plane_coordinate(rng, c.center.y + (top ? 0.5f : -0.5f) * c.height, top ? -1.0f : 1.0f, c.height);
        out.ray = Ray{o, d};
    } else {  // parallel to the axis, inside, on or outside the wall
        const vec3 side = flat_direction(rng, 1);
        const float r = uniform(rng, 0, 1) < 0.4f ? c.radius : c.radius * uniform(rng, 0.0f, 1.5f);
        vec3 o = c.center + side * r;
        o.y = c.center.y - 3.0f * c.height;
        out.ray = Ray{o, vec3(0, 1, 0)};
    }
    return true;
}
bool parallel_case(CaseRng& rng, Case<collision::Capsule>& out) {
    const collision::Capsule c = make_shape<collision::Capsule>(rng, 1.0f, in_cube(rng));
    out.shape = c;
    if (uniform(rng, 0, 1) < 0.5f) {  // horizontal through the seam of wall and hemisphere
        const vec3 d = flat_direction(rng, 1);
        vec3 o = c.center - d * (3.0f * extent(c)) + glm::cross(d, vec3(0, 1, 0)) * (c.radius * uniform(rng, -1.2f, 1.2f));
        o.y = plane_coordinate(rng, c.center.y + 0.5f * c.height, -1.0f, c.height);
        out.ray = Ray{o, d};
    } else {
        const vec3 side = flat_direction(rng, 1);
        const float r = uniform(rng, 0, 1) < 0.4f ? c.radius : c.radius * uniform(rng, 0.0f, 1.5f);
        vec3 o = c.center + side * r;
        o.y = c.center.y - 3.0f * (c.height + c.radius);
        out.ray = Ray{o, vec3(0, 1, 0)};
    }
    return true;
}
bool parallel_case(CaseRng& rng, Case<collision::OrientedCapsule>& out) {
    const collision::OrientedCapsule c = make_shape<collision::OrientedCapsule>(rng, 1.0f, in_cube(rng));
    const vec3 axis = c.b - c.a;
    const vec3 side = glm::normalize(glm::cross(axis, unit_vector(rng)));
    const float r = uniform(rng, 0, 1) < 0.4f ? c.radius : c.radius * uniform(rng, 0.0f, 1.5f);
    out.shape = c;
    out.ray = Ray{c.a - 2.0f * axis + side * r, axis};
    return true;
}
// Flat shapes parallel cases: put them in a y = const plane so a ray can be exactly parallel.
template <class S>
bool flat_parallel(CaseRng& rng, Case<S>& out, const S& shape, float plane_y, float size) {
    const vec3 d = flat_direction(rng, 1);
    vec3 o = centre(shape) - d * (3.0f * size) + glm::cross(d, vec3(0, 1, 0)) * (size * uniform(rng, -1.0f, 1.0f));
    o.y = plane_coordinate(rng, plane_y, 1.0f, size);
    out.shape = shape;
    out.ray = Ray{o, d};
    return true;
}
bool parallel_case(CaseRng& rng, Case<collision::Plane>& out) {
    const vec3 c = in_cube(rng);
    return flat_parallel(rng, out, collision::Plane{c, vec3(0, 1, 0)}, c.y, 1.0f);
}
bool parallel_case(CaseRng& rng, Case<collision::Disk>& out) {
    const vec3 c = in_cube(rng);
    const float r = uniform(rng, 0.5f, 1.0f);
    return flat_parallel(rng, out, collision::Disk{c, vec3(0, 1, 0), r}, c.y, r);
}
bool parallel_case(CaseRng& rng, Case<collision::Quad>& out) {
    const vec3 c = in_cube(rng);
    const vec3 u = flat_direction(rng, 1) * uniform(rng, 0.6f, 1.4f);
    const vec3 v = glm::cross(vec3(0, 1, 0), u) * uniform(rng, 0.6f, 1.4f);
    return flat_parallel(rng, out, collision::Quad{c, u, v}, c.y, glm::length(u));
}
bool parallel_case(CaseRng& rng, Case<collision::Triangle>& out) {
    const vec3 c = in_cube(rng);
    collision::Triangle t{c + flat_direction(rng, 1), c + flat_direction(rng, 1), c + flat_direction(rng, 1)};
    t.b.y = t.c.y = t.a.y;
    if (glm::length(glm::cross(t.b - t.a, t.c - t.a)) < 0.05f) return parallel_case(rng, out);
    return flat_parallel(rng, out, t, t.a.y, 1.0f);
}

// Edges of single closed shapes: rays from inside through a corner / edge point / rim point.
bool edge_case(CaseRng& rng, Case<collision::Aabb>& out) {
    const collision::Aabb b = make_shape<collision::Aabb>(rng, 1.0f, in_cube(rng));
    const vec3 lo = b.min(), hi = b.max();
    vec3 target;
    for (int k = 0; k < 3; ++k) target[k] = uniform(rng, 0, 1) < 0.5f ? lo[k] : hi[k];
    if (uniform(rng, 0, 1) < 0.5f) {  // a point on an edge rather than a corner
        const int free_axis = std::uniform_int_distribution<int>(0, 2)(rng);
        target[free_axis] = uniform(rng, lo[free_axis], hi[free_axis]);
    }
    const vec3 origin = uniform(rng, 0, 1) < 0.5f ? b.center : b.center + 0.3f * b.size * in_cube(rng);
    out.shape = b;
    out.ray = Ray{origin, target - origin};
    return true;
}
bool edge_case(CaseRng& rng, Case<collision::Cylinder>& out) {
    const collision::Cylinder c = make_shape<collision::Cylinder>(rng, 1.0f, in_cube(rng));
    const vec3 side = flat_direction(rng, 1);
    vec3 target = c.center + side * c.radius;
    target.y = c.center.y + (uniform(rng, 0, 1) < 0.5f ? 0.5f : -0.5f) * c.height;
    const vec3 origin = c.center + vec3(0.3f * c.radius, 0.3f * c.height, 0.3f * c.radius) * in_cube(rng);
    out.shape = c;
    out.ray = Ray{origin, target - origin};
    return true;
}
template <class S>
bool edge_case(CaseRng&, Case<S>&) {
    return false;
}

}  // namespace

template <class Shape>
bool shape_is_closed() {
    return !is_flat<Shape>();
}

template <class S>
bool family_applies(Family f) {
    if (f == Family::Parallel) {
        return !std::is_same_v<S, collision::Sphere> && !std::is_same_v<S, collision::Ellipsoid>;
    }
    if (f == Family::Edges) {
        return std::is_same_v<S, collision::Aabb> || std::is_same_v<S, collision::Cylinder> ||
               std::is_same_v<S, collision::Quad> || std::is_same_v<S, collision::Triangle>;
    }
    return true;
}

template <class S>
std::vector<Case<S>> make_cases(Family f, std::size_t n, std::uint64_t seed) {
    // One stream per (family, shape): adding a shape or a family never changes the others.
    const std::uint64_t salt = std::hash<std::string>{}(std::string(family_name(f)) + shape_name<S>());
    CaseRng rng(seed ^ salt);
    std::vector<Case<S>> cases;
    cases.reserve(n);
    Case<S> c;
    for (std::size_t i = 0; i < n; ++i) {
        switch (f) {
            case Family::Uniform:
                c.shape = make_shape<S>(rng, 1.0f, in_cube(rng));
                c.ray = aimed_ray(rng, c.shape, extent(c.shape) * uniform(rng, 3.0f, 6.0f));
                break;
            case Family::Grazing:
                if (!grazing_case(rng, c)) continue;
                break;
            case Family::Far:
                c.shape = make_shape<S>(rng, 1.0f, in_cube(rng));
                c.ray = aimed_ray(rng, c.shape, extent(c.shape) * std::pow(10.0f, uniform(rng, 0.0f, 6.0f)));
                break;
            case Family::Huge:
                c.shape = make_shape<S>(rng, 1e5f, 1e5f * in_cube(rng));
                c.ray = aimed_ray(rng, c.shape, extent(c.shape) * uniform(rng, 3.0f, 6.0f));
                break;
            case Family::Tiny:
                c.shape = make_shape<S>(rng, 1e-4f, in_cube(rng));
                c.ray = aimed_ray(rng, c.shape, uniform(rng, 0.5f, 1.0f));
                break;
            case Family::SurfaceOut:
            case Family::SurfaceIn: {
                const float scale = std::pow(10.0f, uniform(rng, -4.0f, 5.0f));
                c.shape = make_shape<S>(rng, scale, scale * 2.0f * in_cube(rng));
                c.ray = aimed_ray(rng, c.shape, extent(c.shape) * uniform(rng, 3.0f, 6.0f), 0.7f);
                c.secondary_dir = unit_vector(rng);
                break;
            }
            case Family::Parallel:
                if (!parallel_case(rng, c)) return {};
                break;
            case Family::Edges:
                if (!edge_case(rng, c)) return {};
                break;
        }
        cases.push_back(c);
    }
    return cases;
}

namespace {

std::vector<collision::Triangle> icosphere_impl(int level, const vec3& center, float radius,
                                                std::vector<vec3>* out_vertices, collision::TriangleMesh* out_mesh) {
    using Tri = std::array<std::uint32_t, 3>;
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> v = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
                                 {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
    std::vector<Tri> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                              {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                              {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
        auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            v.push_back(0.5 * (v[a] + v[b]));
            const auto index = static_cast<std::uint32_t>(v.size() - 1);
            midpoint.emplace(key, index);
            return index;
        };
        std::vector<Tri> next;
        for (const Tri& f : faces) {
            const std::uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
            next.push_back({f[0], ab, ca});
            next.push_back({f[1], bc, ab});
            next.push_back({f[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        faces = std::move(next);
    }
    std::vector<vec3> vf(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) vf[i] = center + vec3(glm::normalize(v[i]) * double(radius));
    if (out_mesh) {
        out_mesh->vertices = vf;
        out_mesh->indices.clear();
        for (const Tri& f : faces) out_mesh->indices.push_back({f[0], f[1], f[2]});
        return {};
    }
    std::vector<collision::Triangle> tris;
    tris.reserve(faces.size());
    for (const Tri& f : faces) tris.push_back({vf[f[0]], vf[f[1]], vf[f[2]]});
    if (out_vertices) *out_vertices = std::move(vf);
    return tris;
}

}  // namespace

std::vector<collision::Triangle> icosphere(int level, const vec3& center, float radius, std::vector<vec3>* vertices) {
    return icosphere_impl(level, center, radius, vertices, nullptr);
}

collision::TriangleMesh icosphere_mesh(int level, const vec3& center, float radius) {
    collision::TriangleMesh mesh;
    icosphere_impl(level, center, radius, nullptr, &mesh);
    return mesh;
}

namespace {

std::vector<collision::Quad> cube_of_quads(const vec3& c, float h) {
    const vec3 lo = c - vec3(h), size(2.0f * h);
    const vec3 x(size.x, 0, 0), y(0, size.y, 0), z(0, 0, size.z);
    // Each face's edge_u x edge_v points outward.
    return {collision::Quad{lo, z, y},     collision::Quad{lo + x, y, z}, collision::Quad{lo, x, z},
            collision::Quad{lo + y, z, x}, collision::Quad{lo, y, x},     collision::Quad{lo + z, x, y}};
}

}  // namespace

template <class Face>
std::vector<ClosedMeshCase<Face>> make_closed_meshes(std::size_t n, std::uint64_t seed) {
    CaseRng rng(seed ^ std::hash<std::string>{}(std::string("edges-mesh") + shape_name<Face>()));
    constexpr std::size_t rays_per_mesh = 256;
    std::vector<ClosedMeshCase<Face>> meshes;
    for (std::size_t done = 0; done < n; done += rays_per_mesh) {
        ClosedMeshCase<Face> m;
        const float scale = std::pow(10.0f, uniform(rng, -2.0f, 3.0f));
        const vec3 c = uniform(rng, 0, 1) < 0.3f ? vec3(0.0f) : scale * in_cube(rng);
        std::vector<vec3> vertices;
        std::vector<std::pair<vec3, vec3>> edges;
        if constexpr (std::is_same_v<Face, collision::Triangle>) {
            m.faces = icosphere(2, c, scale, &vertices);
            for (const auto& f : m.faces) edges.push_back({f.a, f.b});
        } else {
            m.faces = cube_of_quads(c, scale);
            for (const auto& f : m.faces) {
                vertices.push_back(f.corner);
                edges.push_back({f.corner, f.corner + f.edge_u});
                edges.push_back({f.corner, f.corner + f.edge_v});
            }
        }
        for (std::size_t i = 0; i < rays_per_mesh; ++i) {
            // Half the rays start exactly at the centre, so target - origin is exact when the
            // centre is the world origin: those pass exactly through the vertex.
            const vec3 origin = uniform(rng, 0, 1) < 0.5f ? c : c + 0.3f * scale * in_ball(rng);
            vec3 target;
            if (uniform(rng, 0, 1) < 0.5f) {
                target = vertices[std::uniform_int_distribution<std::size_t>(0, vertices.size() - 1)(rng)];
            } else {
                const auto& e = edges[std::uniform_int_distribution<std::size_t>(0, edges.size() - 1)(rng)];
                const float s = uniform(rng, 0, 1) < 0.5f ? 0.5f : uniform(rng, 0.0f, 1.0f);
                target = e.first + s * (e.second - e.first);
            }
            m.rays.push_back(Ray{origin, target - origin});
        }
        meshes.push_back(std::move(m));
    }
    return meshes;
}

#define SWEEPTRACE_ACCURACY_SHAPE(S)                                                  \
    template bool shape_is_closed<S>();                                               \
    template bool family_applies<S>(Family);                                          \
    template std::vector<Case<S>> make_cases<S>(Family, std::size_t, std::uint64_t);
SWEEPTRACE_ACCURACY_SHAPE(collision::Sphere)
SWEEPTRACE_ACCURACY_SHAPE(collision::Aabb)
SWEEPTRACE_ACCURACY_SHAPE(collision::Cylinder)
SWEEPTRACE_ACCURACY_SHAPE(collision::Capsule)
SWEEPTRACE_ACCURACY_SHAPE(collision::OrientedCapsule)
SWEEPTRACE_ACCURACY_SHAPE(collision::Ellipsoid)
SWEEPTRACE_ACCURACY_SHAPE(collision::Plane)
SWEEPTRACE_ACCURACY_SHAPE(collision::Disk)
SWEEPTRACE_ACCURACY_SHAPE(collision::Quad)
SWEEPTRACE_ACCURACY_SHAPE(collision::Triangle)
#undef SWEEPTRACE_ACCURACY_SHAPE

template std::vector<ClosedMeshCase<collision::Triangle>> make_closed_meshes<collision::Triangle>(std::size_t, std::uint64_t);
template std::vector<ClosedMeshCase<collision::Quad>> make_closed_meshes<collision::Quad>(std::size_t, std::uint64_t);

}  // namespace sweeptrace::accuracy

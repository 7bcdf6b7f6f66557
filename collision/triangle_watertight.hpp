#pragma once
// Watertight ray-triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013), exposed inline for the BVH's inner loop. intersect(Ray,
// Triangle) in intersect_triangle.cpp is prepare + candidate + finish in one call.
//
// Why watertight: the ray is sheared so it becomes the +z axis, and the hit/miss decision uses
// three 2D edge functions of the projected vertices. An edge shared by two triangles yields the
// same edge function (negated) in both, so a ray through the edge is inside at least one of
// them; when an edge function rounds to exactly 0 it is recomputed in double, where the
// products of floats are exact, so the sign is right. No ray leaks through a closed mesh.
// collision/intersect_quad.cpp decides with the same shear_vertex / edge_function, so edges
// shared between quads and triangles (bit-identical endpoints) are watertight as well.
//
// Use by an acceleration structure:
//   TriangleRay tr = prepare_triangle_ray(ray);            // once per ray
//   TriangleCandidate c;
//   if (intersect_triangle_candidate(ray, tr, a, b, c0, c)) { ray.tmax = c.t; keep (prim, c); }
//   ... finish_triangle_hit(a, b, c0, best, hit);           // once, for the nearest
// The candidate step does every check (range, degenerate triangle, non-finite input), so a
// candidate is always a real hit; finish only computes the point, its error, normal and uv.
//
// Error bounds (float; eps = 2^-24, gamma(n) = n eps / (1 - n eps)), pbrt-v4 §6.8.4 notation:
// xt, yt, zt the sheared vertex coordinates (zt scaled by 1/d_z, z = the unscaled one before),
// e_i the edge functions, det = sum e_i,
//   dx = gamma(5) (max|xt| + max|z|), dy = gamma(5) (max|yt| + max|z|), dz = gamma(3) max|zt|,
//   (pbrt-v4 uses the scaled zt in dx, dy; the shear adds sx * z with the unscaled z, |sx| <= 1,
//   so the unscaled z is the right size when |d| > 1),
//   de = 2 (gamma(2) max|xt| max|yt| + dy max|xt| + dx max|yt|),
//  t:  with dT = 3 (gamma(3) max|e| max|zt| + de max|zt| + dz max|e|), the error of
//      t_scaled = sum e_i zt_i, and dD = 3 de + gamma(4) sum|e_i|, that of det plus the
//      division's two roundings,
//        |t - t_exact| <= (dT + |t| dD) / (|det| - dD)      (when |det| > dD)
//      (T'/D' - T/D = ((T' - T) - t (D' - D)) / D'). Rays nearly in the triangle's plane have a
//      small det: their t is as ill-conditioned as the geometry.
//  Hits with t not certainly positive (t <= dT / |det|, pbrt's deltaT) are rejected
//  when tmin >= 0, so a ray leaving the triangle's own surface never re-hits it at t ~ 0.
//  point: sum b_i p_i with |point_i - exact_i| <= gamma(7) sum_j |b_j p_j,i| (pbrt-v4).
//  normal: normalize((b - a) x (c - a)), the geometric normal (not flipped toward the ray);
//      |normal - exact| <= 6 gamma(4) |b - a| |c - a| / |(b - a) x (c - a)| + gamma(6): each
//      cross component carries gamma(4) of products bounded by |b - a| |c - a| (L1 sum <= 3x),
//      normalising doubles the relative error and adds its own roundings. Slivers (small sine
//      of the angle at a) lose normal accuracy; the hit decision does not depend on it.
//  uv: barycentrics (b1, b2) of b and c; b0 = 1 - b1 - b2 is the weight of a.
// Degenerate input: zero-area triangle (cross product 0), NaN/inf vertex, origin or direction,
// zero direction: false.
#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "collision/finite.hpp"
#include "collision/float_error.hpp"
#include "collision/hit.hpp"
#include "collision/ray.hpp"

namespace collision {

// Per-ray part of the test: the axis permutation and shear that map the ray to +z.
struct TriangleRay {
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;
    bool valid = false;  // false for zero, NaN or infinite direction / origin: every test misses
};

// Written without branches on the direction (table look-ups on comparison bits; the compiler
// turns plain selects back into jumps): for incoherent rays every branch here would be a coin
// toss, and this runs once per ray and mesh. kz is the largest |d| axis (the one
// ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2) picks), kx, ky the next two
// cyclically, swapped when d[kz] < 0.
inline TriangleRay prepare_triangle_ray(const Ray& ray) {
    // Index: bit 0 = ad.x > ad.y, bit 1 = ad.x > ad.z, bit 2 = ad.y > ad.z.
    static constexpr signed char kMajor[8] = {2, 2, 2, 0, 1, 2, 1, 0};
    // Index: 2 kz + (d[kz] < 0): {kx, ky}.
    static constexpr signed char kMinor[6][2] = {{1, 2}, {2, 1}, {2, 0}, {0, 2}, {0, 1}, {1, 0}};
    TriangleRay tr;
    const glm::vec3 ad = glm::abs(ray.dir);
    const int bits = int(ad.x > ad.y) | int(ad.x > ad.z) << 1 | int(ad.y > ad.z) << 2;
    tr.kz = kMajor[bits];
    const float dz = ray.dir[tr.kz];
    const int minor = 2 * tr.kz + int(dz < 0.0f);
    tr.kx = kMinor[minor][0];
    tr.ky = kMinor[minor][1];
    tr.valid = (dz != 0.0f) & std::isfinite(ad.x) & std::isfinite(ad.y) & std::isfinite(ad.z) &
               std::isfinite(ray.origin.x) & std::isfinite(ray.origin.y) & std::isfinite(ray.origin.z);
    if (!tr.valid) return tr;
    tr.sx = -ray.dir[tr.kx] / dz;
    tr.sy = -ray.dir[tr.ky] / dz;
    tr.sz = 1.0f / dz;
    return tr;
}

struct TriangleCandidate {
    float t = 0.0f;
    float b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;  // weights of a, b, c
};

// A vertex in the ray's sheared frame: x, y after the shear, z before scaling by sz. It depends
// only on the vertex's floats and the ray, so every face sharing the vertex gets the same values.
struct ShearedVertex {
    float x = 0.0f, y = 0.0f, z = 0.0f;
};

inline ShearedVertex shear_vertex(const Ray& ray, const TriangleRay& tr, const glm::vec3& p) {
    const glm::vec3 rel = p - ray.origin;
    return {rel[tr.kx] + tr.sx * rel[tr.kz], rel[tr.ky] + tr.sy * rel[tr.kz], rel[tr.kz]};
}

// The 2D edge function of the directed edge p -> q (twice the signed area of origin, p, q).
// The edge q -> p gives exactly the negated value, whichever face (triangle or quad) computes
// it: that is what makes shared edges watertight. Its sign is exact whenever it is non-zero
// (rounding is monotone: fl(a) >= fl(b) when a >= b); a zero is re-decided by
// edge_function_exact.
inline float edge_function(const ShearedVertex& p, const ShearedVertex& q) { return p.x * q.y - p.y * q.x; }

// Products of floats are exact in double: the sign of the result is exact.
inline float edge_function_exact(const ShearedVertex& p, const ShearedVertex& q) {
    return float(double(p.x) * double(q.y) - double(p.y) * double(q.x));
}

inline bool intersect_triangle_candidate(const Ray& ray, const TriangleRay& tr, const glm::vec3& a,
                                         const glm::vec3& b, const glm::vec3& c, TriangleCandidate& out) {
    if (!tr.valid) return false;
    // Shear so the ray is +z (z is scaled later, only if the 2D test passes).
    const ShearedVertex sa = shear_vertex(ray, tr, a), sb = shear_vertex(ray, tr, b), sc = shear_vertex(ray, tr, c);
    float e0 = edge_function(sb, sc);  // edge b-c, weight of a
    float e1 = edge_function(sc, sa);  // edge c-a, weight of b
    float e2 = edge_function(sa, sb);  // edge a-b, weight of c
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
        e0 = edge_function_exact(sb, sc);
        e1 = edge_function_exact(sc, sa);
        e2 = edge_function_exact(sa, sb);
    }
    // Two-sided: all edge functions of one sign (zeros allowed: edges and vertices hit).
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
    const float det = e0 + e1 + e2;
    if (det == 0.0f || !std::isfinite(det)) return false;  // ray in the triangle's plane, or NaN
    const float az = tr.sz * sa.z, bz = tr.sz * sb.z, cz = tr.sz * sc.z;
    const float t_scaled = e0 * az + e1 * bz + e2 * cz;
    // Range test before dividing (sign of det folded in); NaN fails every comparison.
    const float abs_det = std::fabs(det);
    const float ts = det < 0.0f ? -t_scaled : t_scaled;
    if (!(ts > ray.tmin * abs_det) || !(ts < ray.tmax * abs_det)) return false;
    const float inv_det = 1.0f / det;
    const float t = t_scaled * inv_det;
    if (!(t > ray.tmin) || !(t < ray.tmax)) return false;

    if (ray.tmin >= 0.0f) {
        // pbrt-v4's deltaT: is t certainly > 0? (See the error bound in the header comment.)
        const float max_zt = std::max({std::fabs(az), std::fabs(bz), std::fabs(cz)});
        const float max_z = std::max({std::fabs(sa.z), std::fabs(sb.z), std::fabs(sc.z)});
        const float max_xt = std::max({std::fabs(sa.x), std::fabs(sb.x), std::fabs(sc.x)});
        const float max_yt = std::max({std::fabs(sa.y), std::fabs(sb.y), std::fabs(sc.y)});
        const float delta_z = gamma(3) * max_zt;
        const float delta_x = gamma(5) * (max_xt + max_z);
        const float delta_y = gamma(5) * (max_yt + max_z);
        const float delta_e = 2.0f * (gamma(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
        const float max_e = std::max({std::fabs(e0), std::fabs(e1), std::fabs(e2)});
        const float delta_t =
            3.0f * (gamma(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * std::fabs(inv_det);
        if (!(t > delta_t)) return false;
    }

    // Zero-area triangles can still give det != 0 through rounding; reject them here, on the
    // (rare) hit path, so a candidate is always a real hit.
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float n2 = glm::dot(n, n);
    if (!(n2 > 0.0f) || !std::isfinite(n2)) return false;

    out.t = t;
    out.b0 = e0 * inv_det;
    out.b1 = e1 * inv_det;
    out.b2 = e2 * inv_det;
    return true;
}

// Completes a candidate: point, its error bound, unit geometric normal, barycentric uv.
inline void finish_triangle_hit(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                                const TriangleCandidate& cand, RayHit& hit) {
    const glm::vec3 wa = cand.b0 * a, wb = cand.b1 * b, wc = cand.b2 * c;
    hit.t = cand.t;
    hit.point = wa + wb + wc;
    hit.point_error = gamma(7) * (glm::abs(wa) + glm::abs(wb) + glm::abs(wc));
    hit.normal = glm::normalize(glm::cross(b - a, c - a));
    hit.uv = glm::vec2(cand.b1, cand.b2);
}

}  // namespace collision

// The wide BVH's kernels for AVX2: one 8-lane slab test per node, and the watertight test on
// the up to 8 triangles of a leaf at once (wide_traversal.hpp says why its hits are the scalar
// test's, bit for bit). Reached only when the CPU reports
// AVX2 (simd_path.hpp). Every header is included before the target pragma, so only the
// functions of this file and wide_traversal.hpp's (internal linkage) are compiled for AVX2;
// "fma" is deliberately not enabled: no multiply-add may change a rounding.
#include <immintrin.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>

#include "collision/triangle_watertight.hpp"
#include "raytracer/accel/bvh_traversal.hpp"
#include "raytracer/accel/object_candidates.hpp"
#include "raytracer/accel/wide_bvh.hpp"
#include "raytracer/accel/wide_kernels.hpp"

#pragma GCC push_options
#pragma GCC target("avx2")

#include "raytracer/accel/wide_traversal.hpp"

namespace sweeptrace {
namespace {

struct Avx2Kernel {
    struct Boxes {
        __m256 ox, oy, oz, ix, iy, iz, fx, fy, fz;
        std::uint32_t near_offset[3], far_offset[3];

        explicit Boxes(const WideRay& r)
            : ox(_mm256_set1_ps(r.origin[0])), oy(_mm256_set1_ps(r.origin[1])), oz(_mm256_set1_ps(r.origin[2])),
              ix(_mm256_set1_ps(r.inv_dir[0])), iy(_mm256_set1_ps(r.inv_dir[1])), iz(_mm256_set1_ps(r.inv_dir[2])),
              fx(_mm256_set1_ps(r.inv_dir_far[0])), fy(_mm256_set1_ps(r.inv_dir_far[1])), fz(_mm256_set1_ps(r.inv_dir_far[2])),
              near_offset{r.near_offset[0], r.near_offset[1], r.near_offset[2]},
              far_offset{r.far_offset[0], r.far_offset[1], r.far_offset[2]} {}

        unsigned test(const WideNode& node, float tmin, float tmax, float* t_enter) const {
            const __m256 tx0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, near_offset[0])), ox), ix);
            const __m256 ty0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, near_offset[1])), oy), iy);
            const __m256 tz0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, near_offset[2])), oz), iz);
            const __m256 tx1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, far_offset[0])), ox), fx);
            const __m256 ty1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, far_offset[1])), oy), fy);
            const __m256 tz1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, far_offset[2])), oz), fz);
            // vmaxps(a, b) = a > b ? a : b and vminps(a, b) = a < b ? a : b: b when a is NaN,
            // exactly the scalar kernel's selects.
            __m256 t0 = _mm256_max_ps(tx0, _mm256_set1_ps(tmin));
            t0 = _mm256_max_ps(ty0, t0);
            t0 = _mm256_max_ps(tz0, t0);
            __m256 t1 = _mm256_min_ps(tx1, _mm256_set1_ps(tmax));
            t1 = _mm256_min_ps(ty1, t1);
            t1 = _mm256_min_ps(tz1, t1);
            _mm256_store_ps(t_enter, t0);
            return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OQ)));
        }
    };

    struct Triangles {
        static constexpr bool tests_lanes = true;  // test() finishes lanes itself (LeafCandidates)
        __m256 ox, oy, oz, sx, sy, sz;  // origin components along the test's kx, ky, kz; the shear
        int kx, ky, kz;

        Triangles(const collision::Ray& ray, const collision::TriangleRay& tr)
            : ox(_mm256_set1_ps(ray.origin[tr.kx])), oy(_mm256_set1_ps(ray.origin[tr.ky])),
              oz(_mm256_set1_ps(ray.origin[tr.kz])), sx(_mm256_set1_ps(tr.sx)), sy(_mm256_set1_ps(tr.sy)),
              sz(_mm256_set1_ps(tr.sz)), kx(tr.kx), ky(tr.ky), kz(tr.kz) {}

        // collision::shear_vertex of 8 vertices: rel = p - o, x = rel_kx + sx rel_kz, y = rel_ky + sy rel_kz, z = rel_kz.
        void shear(const float* v, std::uint32_t count, __m256& x, __m256& y, __m256& z) const {
            z = _mm256_sub_ps(_mm256_loadu_ps(v + kz * count), oz);
            x = _mm256_add_ps(_mm256_sub_ps(_mm256_loadu_ps(v + kx * count), ox), _mm256_mul_ps(sx, z));
            y = _mm256_add_ps(_mm256_sub_ps(_mm256_loadu_ps(v + ky * count), oy), _mm256_mul_ps(sy, z));
        }

        static __m256 abs(__m256 v) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), v); }
        static __m256 max3(__m256 a, __m256 b, __m256 c) { return _mm256_max_ps(_mm256_max_ps(a, b), c); }
        static __m256 mul(__m256 a, __m256 b) { return _mm256_mul_ps(a, b); }
        static __m256 add(__m256 a, __m256 b) { return _mm256_add_ps(a, b); }
        static unsigned bits(__m256 m) { return static_cast<unsigned>(_mm256_movemask_ps(m)); }

        // intersect_triangle_candidate on the leaf's (<= 8) triangles at once, every float
        // operation the scalar test's in its order (wide_traversal.hpp). Lanes with an edge
        // function of 0 go to `exact`, for the scalar test itself (it re-decides them in double);
        // the returned lanes passed every check against (tmin, tmax), their values in `out`.
        unsigned test(const float* block, std::uint32_t count, float tmin, float tmax, LeafCandidates& out,
                      unsigned& exact) const {
            const unsigned lanes = (1u << count) - 1u;
            const __m256 zero = _mm256_setzero_ps();
            __m256 xa, ya, za, xb, yb, zb, xc, yc, zc;
            shear(block, count, xa, ya, za);
            shear(block + 3 * count, count, xb, yb, zb);
            shear(block + 6 * count, count, xc, yc, zc);
            const __m256 e0 = _mm256_sub_ps(mul(xb, yc), mul(yb, xc));
            const __m256 e1 = _mm256_sub_ps(mul(xc, ya), mul(yc, xa));
            const __m256 e2 = _mm256_sub_ps(mul(xa, yb), mul(ya, xb));
            const __m256 neg = _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(e0, zero, _CMP_LT_OQ), _mm256_cmp_ps(e1, zero, _CMP_LT_OQ)),
                                            _mm256_cmp_ps(e2, zero, _CMP_LT_OQ));
            const __m256 pos = _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(e0, zero, _CMP_GT_OQ), _mm256_cmp_ps(e1, zero, _CMP_GT_OQ)),
                                            _mm256_cmp_ps(e2, zero, _CMP_GT_OQ));
            const unsigned zeros = bits(_mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(e0, zero, _CMP_EQ_OQ), _mm256_cmp_ps(e1, zero, _CMP_EQ_OQ)),
                                                     _mm256_cmp_ps(e2, zero, _CMP_EQ_OQ))) & lanes;
            exact = zeros;
            const unsigned inside = ~bits(_mm256_and_ps(neg, pos)) & lanes & ~zeros;
            if (inside == 0) return 0;  // the common leaf: the ray passes beside every triangle
            const __m256 det = add(add(e0, e1), e2);
            const __m256 abs_det = abs(det);
            __m256 ok = _mm256_and_ps(_mm256_cmp_ps(det, zero, _CMP_NEQ_OQ),
                                      _mm256_cmp_ps(abs_det, _mm256_set1_ps(std::numeric_limits<float>::infinity()), _CMP_LT_OQ));
            const __m256 az = mul(sz, za), bz = mul(sz, zb), cz = mul(sz, zc);
            const __m256 t_scaled = add(add(mul(e0, az), mul(e1, bz)), mul(e2, cz));
            const __m256 ts = _mm256_blendv_ps(t_scaled, _mm256_xor_ps(t_scaled, _mm256_set1_ps(-0.0f)),
                                               _mm256_cmp_ps(det, zero, _CMP_LT_OQ));
            const __m256 vtmin = _mm256_set1_ps(tmin), vtmax = _mm256_set1_ps(tmax);
            ok = _mm256_and_ps(ok, _mm256_cmp_ps(ts, mul(vtmin, abs_det), _CMP_GT_OQ));
            ok = _mm256_and_ps(ok, _mm256_cmp_ps(ts, mul(vtmax, abs_det), _CMP_LT_OQ));
            // A ray leaving a surface meets its own triangle's plane behind the origin: the range
            // test fails, and the division and the error bound would be wasted on that lane.
            if ((bits(ok) & inside) == 0) return 0;
            const __m256 inv_det = _mm256_div_ps(_mm256_set1_ps(1.0f), det);
            const __m256 t = mul(t_scaled, inv_det);
            ok = _mm256_and_ps(ok, _mm256_and_ps(_mm256_cmp_ps(t, vtmin, _CMP_GT_OQ), _mm256_cmp_ps(t, vtmax, _CMP_LT_OQ)));
            if (tmin >= 0.0f) {
                const __m256 max_zt = max3(abs(az), abs(bz), abs(cz));
                const __m256 max_z = max3(abs(za), abs(zb), abs(zc));
                const __m256 max_xt = max3(abs(xa), abs(xb), abs(xc));
                const __m256 max_yt = max3(abs(ya), abs(yb), abs(yc));
                const __m256 delta_z = mul(_mm256_set1_ps(collision::gamma(3)), max_zt);
                const __m256 delta_x = mul(_mm256_set1_ps(collision::gamma(5)), add(max_xt, max_z));
                const __m256 delta_y = mul(_mm256_set1_ps(collision::gamma(5)), add(max_yt, max_z));
                const __m256 delta_e = mul(_mm256_set1_ps(2.0f), add(add(mul(mul(_mm256_set1_ps(collision::gamma(2)), max_xt), max_yt),
                                                                         mul(delta_y, max_xt)),
                                                                     mul(delta_x, max_yt)));
                const __m256 max_e = max3(abs(e0), abs(e1), abs(e2));
                const __m256 sum = add(add(mul(mul(_mm256_set1_ps(collision::gamma(3)), max_e), max_zt), mul(delta_e, max_zt)),
                                       mul(delta_z, max_e));
                const __m256 delta_t = mul(mul(_mm256_set1_ps(3.0f), sum), abs(inv_det));
                ok = _mm256_and_ps(ok, _mm256_cmp_ps(t, delta_t, _CMP_GT_OQ));
            }
            const unsigned hits = bits(ok) & inside;
            if (hits == 0) return 0;
            _mm256_store_ps(out.t, t);
            _mm256_store_ps(out.ts, ts);
            _mm256_store_ps(out.abs_det, abs_det);
            _mm256_store_ps(out.inv_det, inv_det);
            _mm256_store_ps(out.e0, e0);
            _mm256_store_ps(out.e1, e1);
            _mm256_store_ps(out.e2, e2);
            return hits;
        }
    };

    // collision::intersect_sphere_candidate on a node's sphere children at once: every float
    // operation of the scalar test (stable_roots, pick_root, reproject's check) in its order,
    // glm::dot as x + y then + z; sqrt and division are IEEE in both.
    struct Spheres {
        static constexpr bool tests_lanes = true;
        __m256 ox, oy, oz, dx, dy, dz, a;
        bool valid;

        explicit Spheres(const collision::Ray& ray)
            : ox(_mm256_set1_ps(ray.origin.x)), oy(_mm256_set1_ps(ray.origin.y)), oz(_mm256_set1_ps(ray.origin.z)),
              dx(_mm256_set1_ps(ray.dir.x)), dy(_mm256_set1_ps(ray.dir.y)), dz(_mm256_set1_ps(ray.dir.z)) {
            const float a_scalar = glm::dot(ray.dir, ray.dir);
            a = _mm256_set1_ps(a_scalar);
            valid = a_scalar > 0.0f && std::isfinite(a_scalar);
        }

        static __m256 mul(__m256 p, __m256 q) { return _mm256_mul_ps(p, q); }
        static __m256 add(__m256 p, __m256 q) { return _mm256_add_ps(p, q); }
        static __m256 sub(__m256 p, __m256 q) { return _mm256_sub_ps(p, q); }
        static __m256 dot(__m256 px, __m256 py, __m256 pz, __m256 qx, __m256 qy, __m256 qz) {
            return add(add(mul(px, qx), mul(py, qy)), mul(pz, qz));
        }
        static __m256 finite(__m256 v) {
            return _mm256_cmp_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), v), _mm256_set1_ps(std::numeric_limits<float>::infinity()),
                                 _CMP_LT_OQ);
        }
        static unsigned bits(__m256 m) { return static_cast<unsigned>(_mm256_movemask_ps(m)); }

        // Of the children in `mask`, `taken` = the sphere ones; returned: those hit within
        // (tmin, tmax), their t in `out`. `scalar` is left 0 (every lane decided here).
        unsigned test(const ChildSpheres& s, unsigned mask, float tmin, float tmax, LaneTimes& out, unsigned& scalar,
                      unsigned& taken) const {
            scalar = 0;
            const __m256 zero = _mm256_setzero_ps(), sign = _mm256_set1_ps(-0.0f);
            const __m256 r = _mm256_load_ps(s.r);
            __m256 ok = _mm256_and_ps(_mm256_cmp_ps(r, zero, _CMP_GT_OQ), finite(r));
            taken = bits(_mm256_cmp_ps(r, zero, _CMP_GT_OQ)) & mask;
            if (taken == 0 || !valid) return 0;
            const __m256 cx = _mm256_load_ps(s.x), cy = _mm256_load_ps(s.y), cz = _mm256_load_ps(s.z);
            const __m256 fx = sub(ox, cx), fy = sub(oy, cy), fz = sub(oz, cz);
            const __m256 b = dot(fx, fy, fz, dx, dy, dz);
            const __m256 ba = _mm256_div_ps(b, a);
            const __m256 lx = sub(fx, mul(ba, dx)), ly = sub(fy, mul(ba, dy)), lz = sub(fz, mul(ba, dz));
            const __m256 l_len = _mm256_sqrt_ps(dot(lx, ly, lz, lx, ly, lz));
            const __m256 disc = mul(sub(r, l_len), add(r, l_len));
            ok = _mm256_and_ps(ok, _mm256_and_ps(_mm256_cmp_ps(disc, zero, _CMP_GE_OQ), finite(disc)));
            if ((bits(ok) & taken) == 0) return 0;  // the common case: every sphere missed
            const __m256 c = sub(dot(fx, fy, fz, fx, fy, fz), mul(r, r));
            ok = _mm256_and_ps(ok, finite(c));
            const __m256 root = _mm256_sqrt_ps(mul(a, disc));
            const __m256 signed_root = _mm256_or_ps(_mm256_andnot_ps(sign, root), _mm256_and_ps(sign, b));
            const __m256 q = _mm256_xor_ps(add(b, signed_root), sign);
            const __m256 t0q = _mm256_div_ps(c, q), t1q = _mm256_div_ps(q, a);
            const __m256 swap = _mm256_cmp_ps(t0q, t1q, _CMP_GT_OQ);
            const __m256 q_zero = _mm256_cmp_ps(q, zero, _CMP_EQ_OQ);  // the tangent point at the origin: both 0
            const __m256 t0 = _mm256_blendv_ps(_mm256_blendv_ps(t0q, t1q, swap), zero, q_zero);
            const __m256 t1 = _mm256_blendv_ps(_mm256_blendv_ps(t1q, t0q, swap), zero, q_zero);
            const __m256 vtmin = _mm256_set1_ps(tmin), vtmax = _mm256_set1_ps(tmax);
            const __m256 ok0 = _mm256_and_ps(_mm256_cmp_ps(t0, vtmin, _CMP_GT_OQ), _mm256_cmp_ps(t0, vtmax, _CMP_LT_OQ));
            const __m256 ok1 = _mm256_and_ps(_mm256_cmp_ps(t1, vtmin, _CMP_GT_OQ), _mm256_cmp_ps(t1, vtmax, _CMP_LT_OQ));
            const __m256 t = _mm256_blendv_ps(t1, t0, ok0);
            ok = _mm256_and_ps(ok, _mm256_or_ps(ok0, ok1));
            // reproject_on_sphere's check on ray.at(t) - centre.
            const __m256 vx = sub(add(ox, mul(dx, t)), cx), vy = sub(add(oy, mul(dy, t)), cy), vz = sub(add(oz, mul(dz, t)), cz);
            const __m256 v2 = dot(vx, vy, vz, vx, vy, vz);
            ok = _mm256_and_ps(ok, _mm256_and_ps(_mm256_cmp_ps(v2, zero, _CMP_GT_OQ), finite(v2)));
            const unsigned hits = bits(ok) & taken;
            if (hits != 0) _mm256_store_ps(out.t, t);
            return hits;
        }
    };
};

}  // namespace

const WideKernels kAvx2Kernels = make_kernels<Avx2Kernel>();

}  // namespace sweeptrace

#pragma GCC pop_options

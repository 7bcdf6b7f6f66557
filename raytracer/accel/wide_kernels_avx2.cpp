// The wide BVH's kernels for AVX2: one 8-lane slab test per node, and the watertight test on
// the up to 8 triangles of a leaf at once (wide_traversal.hpp says why its hits are the scalar
// test's, bit for bit). Reached only when the CPU reports
// AVX2 (simd_path.hpp). Every header is included before the target pragma, so only the
// functions of this file and wide_traversal.hpp's (internal linkage) are compiled for AVX2;
// "fma" is deliberately not enabled: no multiply-add may change a rounding.
#include <immintrin.h>

#include <bit>
#include <cstdint>
#include <limits>

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
        __m256 ox, oy, oz, ix, iy, iz;
        std::uint32_t near_offset[3], far_offset[3];

        explicit Boxes(const WideRay& r)
            : ox(_mm256_set1_ps(r.origin[0])), oy(_mm256_set1_ps(r.origin[1])), oz(_mm256_set1_ps(r.origin[2])),
              ix(_mm256_set1_ps(r.inv_dir[0])), iy(_mm256_set1_ps(r.inv_dir[1])), iz(_mm256_set1_ps(r.inv_dir[2])),
              near_offset{r.near_offset[0], r.near_offset[1], r.near_offset[2]},
              far_offset{r.far_offset[0], r.far_offset[1], r.far_offset[2]} {}

        unsigned test(const WideNode& node, float tmin, float tmax, float* t_enter) const {
            const __m256 scale = _mm256_set1_ps(kSlabFarScale);
            const __m256 tx0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, near_offset[0])), ox), ix);
            const __m256 ty0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, near_offset[1])), oy), iy);
            const __m256 tz0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, near_offset[2])), oz), iz);
            const __m256 tx1 =
                _mm256_mul_ps(_mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, far_offset[0])), ox), ix), scale);
            const __m256 ty1 =
                _mm256_mul_ps(_mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, far_offset[1])), oy), iy), scale);
            const __m256 tz1 =
                _mm256_mul_ps(_mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node_plane(node, far_offset[2])), oz), iz), scale);
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
};

}  // namespace

const WideKernels kAvx2Kernels = make_kernels<Avx2Kernel>();

}  // namespace sweeptrace

#pragma GCC pop_options

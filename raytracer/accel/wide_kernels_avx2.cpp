// The wide BVH's kernels for AVX2: one 8-lane slab test per node, and the watertight test's
// shear and edge functions for up to 8 triangles of a leaf per step (wide_traversal.hpp says
// why that pre-filter keeps the scalar test's results). Reached only when the CPU reports
// AVX2 (simd_path.hpp). Every header is included before the target pragma, so only the
// functions of this file and wide_traversal.hpp's (internal linkage) are compiled for AVX2;
// "fma" is deliberately not enabled: no multiply-add may change a rounding.
#include <immintrin.h>

#include <bit>
#include <cstdint>

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
        __m256 ox, oy, oz, sx, sy;  // origin components along the test's kx, ky, kz; the shear
        int kx, ky, kz;

        Triangles(const collision::Ray& ray, const collision::TriangleRay& tr)
            : ox(_mm256_set1_ps(ray.origin[tr.kx])), oy(_mm256_set1_ps(ray.origin[tr.ky])),
              oz(_mm256_set1_ps(ray.origin[tr.kz])), sx(_mm256_set1_ps(tr.sx)), sy(_mm256_set1_ps(tr.sy)), kx(tr.kx),
              ky(tr.ky), kz(tr.kz) {}

        // collision::shear_vertex of 8 vertices: rel = p - o, x = rel_kx + sx rel_kz, y = rel_ky + sy rel_kz.
        void shear(const float* v, std::uint32_t count, __m256& x, __m256& y) const {
            const __m256 rz = _mm256_sub_ps(_mm256_loadu_ps(v + kz * count), oz);
            x = _mm256_add_ps(_mm256_sub_ps(_mm256_loadu_ps(v + kx * count), ox), _mm256_mul_ps(sx, rz));
            y = _mm256_add_ps(_mm256_sub_ps(_mm256_loadu_ps(v + ky * count), oy), _mm256_mul_ps(sy, rz));
        }

        // Lanes of the leaf not certainly missed (edge functions of both strict signs).
        unsigned candidates(const float* block, std::uint32_t count) const {
            unsigned keep = 0;
            const __m256 zero = _mm256_setzero_ps();
            for (std::uint32_t j = 0; j < count; j += 8) {
                __m256 xa, ya, xb, yb, xc, yc;
                shear(block + j, count, xa, ya);
                shear(block + 3 * count + j, count, xb, yb);
                shear(block + 6 * count + j, count, xc, yc);
                const __m256 e0 = _mm256_sub_ps(_mm256_mul_ps(xb, yc), _mm256_mul_ps(yb, xc));
                const __m256 e1 = _mm256_sub_ps(_mm256_mul_ps(xc, ya), _mm256_mul_ps(yc, xa));
                const __m256 e2 = _mm256_sub_ps(_mm256_mul_ps(xa, yb), _mm256_mul_ps(ya, xb));
                const __m256 neg = _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(e0, zero, _CMP_LT_OQ), _mm256_cmp_ps(e1, zero, _CMP_LT_OQ)),
                                                _mm256_cmp_ps(e2, zero, _CMP_LT_OQ));
                const __m256 pos = _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(e0, zero, _CMP_GT_OQ), _mm256_cmp_ps(e1, zero, _CMP_GT_OQ)),
                                                _mm256_cmp_ps(e2, zero, _CMP_GT_OQ));
                const auto mixed = static_cast<unsigned>(_mm256_movemask_ps(_mm256_and_ps(neg, pos)));
                keep |= (~mixed & 0xFFu) << j;
            }
            return keep & ((1u << count) - 1u);
        }
    };
};

}  // namespace

const WideKernels kAvx2Kernels = make_kernels<Avx2Kernel>();

}  // namespace sweeptrace

#pragma GCC pop_options

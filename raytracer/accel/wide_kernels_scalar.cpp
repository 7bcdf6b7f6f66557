// The wide BVH's kernels in plain C++ (the build's baseline ISA): every lane of the box test
// one after the other, and every triangle of a leaf through the scalar watertight test itself. The reference the AVX2 kernels must match bit for bit.
#include "raytracer/accel/wide_traversal.hpp"

namespace sweeptrace {
namespace {

struct ScalarKernel {
    struct Boxes {
        WideRay r;
        explicit Boxes(const WideRay& ray) : r(ray) {}

        unsigned test(const WideNode& node, float tmin, float tmax, float* t_enter) const {
            const float *nx = node_plane(node, r.near_offset[0]), *fx = node_plane(node, r.far_offset[0]);
            const float *ny = node_plane(node, r.near_offset[1]), *fy = node_plane(node, r.far_offset[1]);
            const float *nz = node_plane(node, r.near_offset[2]), *fz = node_plane(node, r.far_offset[2]);
            unsigned mask = 0;
            for (int i = 0; i < kWideWidth; ++i) {
                const float tx0 = (nx[i] - r.origin[0]) * r.inv_dir[0];
                const float tx1 = (fx[i] - r.origin[0]) * r.inv_dir_far[0];
                const float ty0 = (ny[i] - r.origin[1]) * r.inv_dir[1];
                const float ty1 = (fy[i] - r.origin[1]) * r.inv_dir_far[1];
                const float tz0 = (nz[i] - r.origin[2]) * r.inv_dir[2];
                const float tz1 = (fz[i] - r.origin[2]) * r.inv_dir_far[2];
                mask |= static_cast<unsigned>(slab_interval(tx0, tx1, ty0, ty1, tz0, tz1, tmin, tmax, t_enter[i])) << i;
            }
            return mask;
        }
    };

    struct Triangles {  // every triangle to the scalar test itself
        static constexpr bool tests_lanes = false;
        Triangles(const collision::Ray&, const collision::TriangleRay&) {}
        unsigned test(const float*, std::uint32_t count, float, float, LeafCandidates&, unsigned& exact) const {
            exact = (1u << count) - 1u;
            return 0;
        }
    };

    struct Spheres {  // every sphere child to collision::intersect_sphere_candidate itself
        static constexpr bool tests_lanes = false;
        explicit Spheres(const collision::Ray&) {}
        unsigned test(const ChildSpheres& s, unsigned mask, float, float, LaneTimes&, unsigned& scalar,
                      unsigned& taken) const {
            taken = 0;
            for (int lane = 0; lane < kWideWidth; ++lane) taken |= static_cast<unsigned>(s.r[lane] > 0.0f) << lane;
            taken &= mask;
            scalar = taken;
            return 0;
        }
    };
};

}  // namespace

const WideKernels kScalarKernels = make_kernels<ScalarKernel>();

}  // namespace sweeptrace

// Mesh-mesh by the thesis's 8-octant subdivision (3.3.3): a one-level octree per mesh. The
// thesis normalised each mesh into unit bounds at load time and split that box at its centre;
// here the split is of the mesh's own bounding box in place (no rescaled copy), which is the
// same partition. A triangle is listed in every octant its bounding box overlaps (the
// default) or, as in the thesis, in the octants of its vertices (OctantRule::vertices, which
// can miss contacts: see mesh_mesh.hpp). Pairs: whole-mesh boxes first (the thesis's early
// test), then the 8 x 8 octant boxes, then every triangle pair of each overlapping octant pair.
// A triangle pair spanning several octant pairs is tested once per pair (cost, not error).
// The octant boxes are exact float halves: centre = 0.5 lo + 0.5 hi lies in [lo, hi] without
// overflow, and neighbouring octants share it exactly, so closed-box tests leave no gap.
#include "collision/mesh_mesh.hpp"
#include "collision/overlap.hpp"

namespace collision {

OctantPartition build_octants(const TriangleMesh& m, OctantRule rule) {
    validate_mesh(m, "mesh");
    OctantPartition o;
    o.mesh = &m;
    o.bounds = mesh_bounds(m);
    if (o.bounds.empty()) return o;
    const glm::vec3 c = o.bounds.center();
    for (int k = 0; k < 8; ++k) {
        for (int axis = 0; axis < 3; ++axis) {
            const bool upper = (k >> axis) & 1;
            o.octant[k].lo[axis] = upper ? c[axis] : o.bounds.lo[axis];
            o.octant[k].hi[axis] = upper ? o.bounds.hi[axis] : c[axis];
        }
    }
    for (std::uint32_t i = 0; i < m.triangle_count(); ++i) {
        if (rule == OctantRule::boxes) {
            const Bounds3 tb = triangle_bounds(m, i);
            for (int k = 0; k < 8; ++k)
                if (boxes_overlap(tb, o.octant[k])) o.triangles[k].push_back(i);
        } else {
            unsigned seen = 0;
            for (int v = 0; v < 3; ++v) {
                const glm::vec3& p = m.vertices[m.indices[i][v]];
                const int k = (p.x > c.x ? 1 : 0) | (p.y > c.y ? 2 : 0) | (p.z > c.z ? 4 : 0);
                if (!(seen & (1u << k))) o.triangles[k].push_back(i);
                seen |= 1u << k;
            }
        }
    }
    return o;
}

bool overlap_octant(const OctantPartition& a, const OctantPartition& b, MeshPairStats* stats) {
    validate_mesh(*a.mesh, "first mesh");
    validate_mesh(*b.mesh, "second mesh");
    MeshPairStats local;
    bool hit = false;
    ++local.box_tests;
    if (boxes_overlap(a.bounds, b.bounds)) {
        for (int i = 0; i < 8 && !hit; ++i) {
            if (a.triangles[i].empty()) continue;
            for (int j = 0; j < 8 && !hit; ++j) {
                if (b.triangles[j].empty()) continue;
                ++local.box_tests;
                if (!boxes_overlap(a.octant[i], b.octant[j])) continue;
                for (std::uint32_t ta : a.triangles[i]) {
                    const Triangle tri_a = a.mesh->triangle(ta);
                    for (std::uint32_t tb : b.triangles[j]) {
                        ++local.triangle_tests;
                        if (overlap(tri_a, b.mesh->triangle(tb))) {
                            hit = true;
                            break;
                        }
                    }
                    if (hit) break;
                }
            }
        }
    }
    if (stats) {
        stats->box_tests += local.box_tests;
        stats->triangle_tests += local.triangle_tests;
    }
    return hit;
}

}  // namespace collision

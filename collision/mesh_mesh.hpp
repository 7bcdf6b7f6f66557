#pragma once
// Mesh-mesh overlap (thesis 3.3): four ways to answer "do two triangle meshes touch?".
//
//  - overlap_brute:  every triangle of a against every triangle of b (Möller), O(m n), after the
//                    whole meshes' bounding boxes (the thesis's early test). The reference.
//  - overlap_octant: the thesis's one-level octree: each mesh's bounding box split into 8
//                    octants, triangles listed in the octants they touch; only triangle pairs
//                    from overlapping octant pairs are tested.
//  - overlap_bvh:    a bounding volume hierarchy per mesh (collision/bvh.hpp, binned SAH),
//                    descended in pairs; only leaves whose boxes overlap test triangle pairs.
//  - overlap_sat:    the separating axis theorem on the meshes as solids; exact for CONVEX
//                    meshes only (a concave pair can be reported touching when it is not).
//
// What "overlap" means: brute, octant and BVH test the *surfaces* (some triangle of a meets
// some triangle of b, touching included). SAT tests the convex *solids*: for convex meshes it
// also reports one mesh wholly inside the other, which the surface tests do not.
//
// Meshes are used in place (no copy): a built OctantPartition / MeshOverlapBvh keeps a pointer
// to its TriangleMesh, which must outlive it and not change. Every entry point validates its meshes
// and throws std::invalid_argument naming the mesh and the triangle for an index out of range
// or a non-finite vertex. Zero-area triangles never touch anything (Möller's contract).
#include <array>
#include <cstdint>
#include <vector>

#include "collision/bounds3.hpp"
#include "collision/bvh.hpp"
#include "collision/hit.hpp"
#include "collision/mesh.hpp"
#include "collision/mesh_boxes.hpp"

namespace collision {

// Work counters, for comparing the methods (optional out-parameter of every test).
struct MeshPairStats {
    std::uint64_t triangle_tests = 0;  // Möller tests run
    std::uint64_t box_tests = 0;       // box-box overlap tests (octant pairs, BVH node pairs)
    std::uint64_t axis_tests = 0;      // SAT axes projected
};

// Throws std::invalid_argument("<name>: triangle i ...") for a broken mesh.
void validate_mesh(const TriangleMesh& m, const char* name);

// Closed boxes: touching faces count.
bool boxes_overlap(const Bounds3& a, const Bounds3& b);

bool overlap_brute(const TriangleMesh& a, const TriangleMesh& b, MeshPairStats* stats = nullptr);

// Which octants a triangle is listed in. `boxes` (default): every octant its bounding box
// overlaps, which can never miss a contact (a contact point lies in some octant of each mesh,
// and both triangles' boxes contain it). `vertices`: the thesis's rule, the octants holding
// its vertices -- a large triangle crossing an octant without a vertex in it is missing from
// that octant, and contacts there are missed (kept to show it; see test_mesh_mesh.cpp).
enum class OctantRule { boxes, vertices };

struct OctantPartition {
    const TriangleMesh* mesh = nullptr;
    Bounds3 bounds;                                   // the whole mesh
    std::array<Bounds3, 8> octant{};                  // the 8 halves of `bounds` (fixed split)
    std::array<std::vector<std::uint32_t>, 8> triangles;
};
OctantPartition build_octants(const TriangleMesh& m, OctantRule rule = OctantRule::boxes);
bool overlap_octant(const OctantPartition& a, const OctantPartition& b, MeshPairStats* stats = nullptr);

struct MeshOverlapBvh {
    const TriangleMesh* mesh = nullptr;
    Bvh bvh;  // build_triangle_bvh(*mesh): primitive indices are triangle indices
};
MeshOverlapBvh build_overlap_bvh(const TriangleMesh& m);
bool overlap_bvh(const MeshOverlapBvh& a, const MeshOverlapBvh& b, MeshPairStats* stats = nullptr);

// Candidate axes: face normals of both meshes (the thesis's set) and, for `faces_and_edges`,
// the cross products of every edge of a with every edge of b, without which two convex solids
// touching edge to edge can be reported overlapping when they are apart. The default makes
// the test exact for convex meshes, at O((Fa + Fb + Ea Eb)(Va + Vb)) work: fine for the few
// dozen faces of a convex hull, not for scanned meshes.
enum class SatAxes { faces_and_edges, faces };

// hit and the minimal translation of a along the tested axes that separates the solids (for
// convex meshes with faces_and_edges, the true minimal translation vector). Vertices are
// projected once per axis -- O(axes x (Va + Vb)) -- not once per triangle as in the thesis
// (O(m^2 n + n^2 m)).
Contact overlap_sat(const TriangleMesh& a, const TriangleMesh& b, SatAxes axes = SatAxes::faces_and_edges,
                    MeshPairStats* stats = nullptr);

}  // namespace collision

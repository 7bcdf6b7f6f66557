// Mesh-mesh by brute force (thesis 3.3.2) and the helpers all four methods share.
#include <cmath>
#include <stdexcept>
#include <string>

#include "collision/mesh_mesh.hpp"
#include "collision/overlap.hpp"
#include "collision/finite.hpp"

namespace collision {

void validate_mesh(const TriangleMesh& m, const char* name) {
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
        if (!finite(m.vertices[i]))
            throw std::invalid_argument(std::string(name) + ": vertex " + std::to_string(i) + " is not finite");
    for (std::size_t i = 0; i < m.indices.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (m.indices[i][k] >= m.vertices.size())
                throw std::invalid_argument(std::string(name) + ": triangle " + std::to_string(i) + " uses vertex " +
                                            std::to_string(m.indices[i][k]) + " of " +
                                            std::to_string(m.vertices.size()));
}

bool boxes_overlap(const Bounds3& a, const Bounds3& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
           b.lo.z <= a.hi.z;
}

bool overlap_brute(const TriangleMesh& a, const TriangleMesh& b, MeshPairStats* stats) {
    validate_mesh(a, "first mesh");
    validate_mesh(b, "second mesh");
    if (!boxes_overlap(mesh_bounds(a), mesh_bounds(b))) return false;
    std::uint64_t tests = 0;
    bool hit = false;
    for (std::size_t i = 0; i < a.triangle_count() && !hit; ++i) {
        const Triangle ta = a.triangle(i);
        for (std::size_t j = 0; j < b.triangle_count(); ++j) {
            ++tests;
            if (overlap(ta, b.triangle(j))) {
                hit = true;
                break;
            }
        }
    }
    if (stats) stats->triangle_tests += tests;
    return hit;
}

}  // namespace collision

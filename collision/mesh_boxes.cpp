// Triangle boxes, mesh boxes and the triangle BVH (mesh_boxes.hpp).
#include "collision/mesh_boxes.hpp"

#include <vector>

namespace collision {

Bounds3 triangle_bounds(const TriangleMesh& m, std::size_t i) {
    Bounds3 b;
    for (int k = 0; k < 3; ++k) b.extend(m.vertices[m.indices[i][k]]);
    return b;
}

Bounds3 mesh_bounds(const TriangleMesh& m) {
    Bounds3 b;
    for (std::size_t i = 0; i < m.indices.size(); ++i) b.extend(triangle_bounds(m, i));
    return b;
}

Bvh build_triangle_bvh(const TriangleMesh& m, const BvhBuildOptions& options) {
    std::vector<Bounds3> boxes(m.triangle_count());
    std::vector<glm::vec3> centroids(m.triangle_count());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        boxes[i] = triangle_bounds(m, i);
        // The box centre, not the vertex mean: one rounding, and it splits long thin triangles
        // where their extent is.
        centroids[i] = boxes[i].center();
    }
    return build_bvh(boxes, centroids, options);
}

}  // namespace collision

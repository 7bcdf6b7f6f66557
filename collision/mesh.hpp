#pragma once
// An indexed triangle mesh (§2.5, §3.3). The OBJ reader lives in the renderer's scene loader;
// this library knows only vertices and index triples.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "collision/shapes.hpp"

namespace collision {

struct TriangleMesh {
    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> indices;  // counter-clockwise triples into `vertices`

    std::size_t triangle_count() const { return indices.size(); }
    Triangle triangle(std::size_t i) const {
        const glm::uvec3& f = indices[i];
        return Triangle{vertices[f.x], vertices[f.y], vertices[f.z]};
    }
};

}  // namespace collision

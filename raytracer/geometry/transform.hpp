#pragma once
// Affine object-to-world transform. Rays go into object space (the thesis's world-to-view
// trick) so analytic shapes stay analytic; normals come back by the inverse transpose.
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace sweeptrace {

struct Transform {
    glm::mat4 to_world{1.0f};
    glm::mat4 to_object{1.0f};
    glm::mat3 normal_to_world{1.0f};  // inverse transpose of to_world's linear part
    bool identity = true;

    // Throws InputError-free std::invalid_argument when `m` is singular or not finite; the
    // scene loader turns that into a message with the JSON path.
    static Transform from_matrix(const glm::mat4& m);
};

}  // namespace sweeptrace

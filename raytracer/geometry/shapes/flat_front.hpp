#pragma once
// What a flat shape's home (quad, disk, triangle) says about its one side: a point on its plane
// and its front normal, the side a one-sided emitter lights. Closed shapes and meshes have no
// single front and do not define front().
#include <glm/vec3.hpp>

namespace sweeptrace {

struct FlatFront {
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f};  // not unit
};

}  // namespace sweeptrace

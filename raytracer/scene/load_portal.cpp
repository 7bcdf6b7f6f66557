#include "raytracer/scene/load_portal.hpp"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

namespace sweeptrace {

void read_portal(const scene_json::Node& node, Background& background) {
    if (node.array_size() != 4) node.fail("must be 4 corners [[x, y, z], ...] in order round a rectangle, got " + node.shown());
    std::array<glm::vec3, 4> c;
    for (std::size_t i = 0; i < 4; ++i) c[i] = node.element(i).vec3();
    std::array<glm::vec3, 4> edge;  // c0 -> c1 -> c2 -> c3 -> c0
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::vec3 e = c[(i + 1) % 4] - c[i];
        const float length = glm::length(e);
        if (!(length > 0.0f) || !std::isfinite(length))
            node.fail("corners " + std::to_string(i) + " and " + std::to_string((i + 1) % 4) + " must differ (a rectangle)");
        edge[i] = e / length;
    }
    constexpr float kCosineTolerance = 0.001f;  // pbrt-v4's (load_portal.hpp)
    for (std::size_t i = 0; i < 4; ++i) {
        if (std::abs(glm::dot(edge[i], edge[(i + 1) % 4])) > kCosineTolerance)
            node.fail("edges " + std::to_string(i) + " and " + std::to_string((i + 1) % 4) +
                      " are not perpendicular: the corners must be a rectangle, in order round its edge");
    }
    for (std::size_t i = 0; i < 2; ++i) {
        if (std::abs(glm::dot(edge[i], edge[i + 2]) + 1.0f) > kCosineTolerance)
            node.fail("edges " + std::to_string(i) + " and " + std::to_string(i + 2) +
                      " are not parallel: the corners must be a planar rectangle, in order round its edge");
    }
    background.has_portal = true;
    background.portal = c;
}

}  // namespace sweeptrace

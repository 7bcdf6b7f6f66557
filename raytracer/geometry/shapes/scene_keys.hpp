#pragma once
// Reading helpers shared by the shapes' scene keys. Templates over the scene loader's JSON node
// (scene/json_reader.hpp), so a shape's home names its keys without depending on the loader.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace sweeptrace::scene_keys {

template <class Node>
glm::vec3 center_or_origin(const Node& node) {
    if (auto c = node.find("center")) return c->vec3();
    return glm::vec3(0.0f);
}

// Exactly zero in double: the inputs are floats, so differences and cross products of them are
// (nearly) exact in double, and "zero" here means truly degenerate, not "small".
inline bool parallel(const glm::dvec3& a, const glm::dvec3& b) { return glm::cross(a, b) == glm::dvec3(0.0); }

// A strictly positive vec3 (sizes, radii): a bad component is reported at its own path.
template <class Node>
glm::vec3 positive_vec3(const Node& node) {
    const glm::vec3 v = node.vec3();
    for (int k = 0; k < 3; ++k)
        if (!(v[k] > 0.0f)) node.element(static_cast<std::size_t>(k)).number_at_least(0.0f, false);
    return v;
}

}  // namespace sweeptrace::scene_keys

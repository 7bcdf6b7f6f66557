#pragma once
// Lights that are not surfaces, under the scene's top-level "lights" key (scenes/README.md):
// point and spot lights (delta positions) and directional lights, which are at infinity and
// either delta (angular_diameter 0) or a uniform disc of directions (a sun with soft shadows).
// Sampling lives in render/ (LightSet); this is only the validated description.
#include <string>

#include <glm/vec3.hpp>

namespace sweeptrace {

struct SceneLight {
    enum class Type { Point, Spot, Directional };
    Type type = Type::Point;
    glm::vec3 position{0.0f};                // Point, Spot
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // Spot, Directional: unit, the way the light travels
    // Point, Spot: radiant intensity (radiance x area, W/sr) along the axis: a surface at
    // distance d facing the light receives intensity / d^2.
    glm::vec3 intensity{0.0f};
    // Spot: cosines of the cone's half-angle (no light beyond) and of the half-angle where the
    // smooth falloff begins (full intensity inside it); cos_falloff_start >= cos_cone.
    float cos_cone = 0.0f;
    float cos_falloff_start = 0.0f;
    // Directional: irradiance on a surface facing the light (for any angular diameter), and the
    // half-angle of the disc of directions it comes from, in radians (0 = a delta direction).
    glm::vec3 irradiance{0.0f};
    float half_angle = 0.0f;
    std::string name;  // for messages
};

}  // namespace sweeptrace

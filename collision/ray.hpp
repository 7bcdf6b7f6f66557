#pragma once
// A ray, and the swept segment of the thesis: a segment p0 -> p1 is the ray
// {origin = p0, dir = p1 - p0, tmin = 0, tmax = 1}.
#include <glm/vec3.hpp>
#include <limits>

namespace collision {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 dir{0.0f, 0.0f, 1.0f};  // not required to be unit length
    float tmin = 0.0f;
    float tmax = std::numeric_limits<float>::infinity();

    glm::vec3 at(float t) const { return origin + dir * t; }
};

// The thesis's motion segment over one step, as a ray over [0, 1].
inline Ray segment(const glm::vec3& from, const glm::vec3& to) { return Ray{from, to - from, 0.0f, 1.0f}; }

}  // namespace collision

#pragma once
// A scene object: one shape (or a mesh instance) in its own object space, an affine transform to
// world space and a material. Analytic shapes stay analytic.
#include <cstdint>
#include <string>

#include "raytracer/geometry/shape.hpp"
#include "raytracer/geometry/transform.hpp"

namespace sweeptrace {

struct Object {
    Shape shape;
    Transform transform;
    std::uint32_t material = 0;  // index into Scene::materials
    std::string name;            // for messages and statistics
};

}  // namespace sweeptrace

#pragma once
// A scene object: one shape (or a mesh instance) in its own object space, an affine transform to
// world space and a material. Analytic shapes stay analytic. A moving object (scene key "motion")
// also has its keyframes over the shutter (motion.hpp); its `transform` is then the first of them,
// its pose at shutter open, which is what the queries without a time see.
#include <cstdint>
#include <string>

#include "raytracer/geometry/motion.hpp"
#include "raytracer/geometry/shape.hpp"
#include "raytracer/geometry/transform.hpp"

namespace sweeptrace {

struct Object {
    Shape shape;
    Transform transform;
    std::uint32_t material = 0;  // index into Scene::materials
    std::string name;            // for messages and statistics
    Motion motion;               // no keys: the object is still (last, so positional Object{...} lists keep their order)
};

}  // namespace sweeptrace

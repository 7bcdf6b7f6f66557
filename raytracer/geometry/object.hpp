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

// The media on the two sides of an object's surface (indices into Scene::media, -1 vacuum), as
// pbrt-v4's MediumInterface: `inside` is the side opposite the outward geometric normal. When
// they are equal (the default: neither given) the surface is no boundary and a ray keeps the
// medium it arrived in (render/media/scene_media.hpp).
struct MediumInterface {
    std::int32_t inside = -1, outside = -1;
    bool transition() const { return inside != outside; }
};

struct Object {
    Shape shape;
    Transform transform;
    std::uint32_t material = 0;  // index into Scene::materials
    std::string name;            // for messages and statistics
    Motion motion;               // no keys: the object is still (last, so positional Object{...} lists keep their order)
    MediumInterface media;       // scene keys "inside", "outside" (scene/load_media.hpp)
};

}  // namespace sweeptrace

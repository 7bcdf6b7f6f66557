#pragma once
// The scene keys of motion blur (scenes/README.md, "Motion blur"): camera.shutter and an
// object's "motion". Internal to the scene loader, like json_reader.hpp.
//
//   camera.shutter: [open, close], open <= close. Set, each camera ray is traced at a time drawn
//     in it (render/camera.hpp); the poses of moving objects are spaced evenly over it, so only
//     whether it is set, and whether open < close, changes the image.
//   objects[i].motion: { "close": <transform> }: the object moves from its "transform" (its pose
//     at shutter open) to this pose at close; or { "keyframes": [<transform>, ...] }: 2 to 129
//     poses evenly spaced over the shutter, the first at open (the object then has no
//     "transform" of its own). Interpolated as geometry/motion.hpp states.
// Errors (exit 2, one line with the JSON path): shutter open > close; a "motion" in a scene
// without camera.shutter (nothing would move: an error rather than a warning, since the user
// asked for motion and would silently get a still image); a keyframe count outside 2..129; a
// moving object whose material emits or reads a texture (light sampling and texture lookups see
// objects in their pose at shutter open only, so they would be wrong for a moving one).
// Keyframes hold numbers as transforms do: non-finite ones are rejected by the reader. A motion
// whose poses are all equal leaves the object still (Object::motion empty).
#include <optional>

#include "raytracer/scene/json_reader.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// camera.shutter, into `camera`.
void read_shutter(const scene_json::Node& shutter, Camera& camera);

// objects[i].motion, into `object` (its transform becomes keyframes[0] with "keyframes").
// `read_transform` is the loader's reader of a transform list.
void read_motion(const scene_json::Node& motion, const scene_json::Node& object_node, Object& object,
                 Transform (*read_transform)(const scene_json::Node&));

// After the objects are read and split by their OBJ materials: the checks that need the whole
// scene (a shutter for every motion; no emitting or textured material on a moving object).
// `root` is the scene document; `json_objects` how many objects it lists.
void check_motion(const Scene& scene, const scene_json::Node& root, std::size_t json_objects);

}  // namespace sweeptrace

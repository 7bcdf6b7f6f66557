#pragma once
// A check on a loaded scene that is not an error: one-sided flat emitters (quad, disk, triangle
// with an emission and two_sided false) turned away from the scene. Two rules, on world boxes
// (object_world_bounds):
// - every other object's box lies on or behind the emitter's plane: the light certainly lights
//   nothing directly (the rule the issue asks for);
// - both the camera and the centre of the box around all other objects lie on or behind the
//   plane: the light faces out of the scene and is not seen. This catches the common case the
//   first rule misses, a ceiling light with its edges swapped: it faces the ceiling a unit above
//   it (and the walls' top unit), so some box is in front, yet the room renders black. It can
//   also flag a light turned away on purpose toward something at the scene's edge; it is a
//   warning, not an error. (The scene's centre alone is not enough: primitives.json has a disk
//   light turned toward the camera, away from the middle of its large floor.)
// Closed shapes and meshes have no single front and are not checked; a scene with only the
// emitter is not reported either.
#include <string>
#include <vector>

#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

// One line per such emitter: "<file>: <object name>: ...", for `sweeptrace: warning: ` to prefix.
std::vector<std::string> emitters_facing_nothing(const Scene& scene);

}  // namespace sweeptrace

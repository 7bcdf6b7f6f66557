#pragma once
// Media inside media with no way out, found before rendering: a boundary whose declared side
// disagrees with the surface it faces. pbrt-v4 takes each MediumInterface on trust, so a glass
// sphere whose "outside" says vacuum while it sits in a fog box renders a sphere surrounded by a
// hole in the fog, and a camera whose medium is not the one around it sees the wrong medium up
// to the first boundary. With the scene's accelerator both can be checked once.
//
// The probe: for each object that is a boundary (MediumInterface::transition(), geometry/
// object.hpp), points on its surface are found by rays through its box's centre in eight
// directions, one per octant (each first hit on that object; media_nesting.cpp says why those
// directions); from each point a ray leaves along the outward normal
// and one along the inward normal. The first surface such a ray meets, if it is a boundary,
// says which medium is on the side the ray arrives from (its outside when the ray meets its
// front); that must be the side the probe left from (the object's outside, or its inside).
// The camera is probed the same way: rays from its position along the six axes and its view
// direction must arrive in camera.medium.
//
// What says nothing: a surface that is no boundary (a wall in fog keeps whatever medium is
// around it: it may sit in any, so the probe stops there without a verdict), and a ray that
// leaves the scene (unbounded fog around the camera is legitimate). Open surfaces (a quad, a
// disk, an open mesh) are boundaries like closed ones: a probe leaves each side along the normal
// and checks the first boundary it meets there, which is where light leaving that side goes
// first. An inconsistency no probe meets (two objects that overlap by a sliver away from the
// probe points) is not found: the check finds contradictions, it does not prove their absence.
//
// A mismatch throws InputError naming the scene file, both objects (their scene names: the
// JSON path and shape, a "name" key, or the pbrt file and line the importer gives them), the
// point, and the two media. Still objects in their pose at shutter open are probed.
#include "raytracer/accel/accel.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

void check_media_nesting(const Scene& scene, const Accel& accel);

}  // namespace sweeptrace

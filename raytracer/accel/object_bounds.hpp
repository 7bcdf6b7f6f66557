#pragma once
// World-space boxes of scene objects, for the top level of the BVH and for Embree's user
// geometry. Conservative: each box holds the exact transformed surface.
#include "collision/bounds3.hpp"
#include "raytracer/geometry/object.hpp"

namespace sweeptrace {

// Box of an analytic shape in its object space, each bound rounded outward so it holds the
// exact shape. MeshInstance: not analytic, the caller passes the mesh's own box instead.
collision::Bounds3 object_space_bounds(const Shape& shape);

// The object-space box mapped to world: the 8 transformed corners, each padded by its
// transformation error bound (object_space.hpp's point_to_world), so the result holds the
// exact image of the box under to_world.
collision::Bounds3 world_bounds(const Transform& xf, const collision::Bounds3& object_box);

}  // namespace sweeptrace

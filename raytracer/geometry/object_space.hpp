#pragma once
// Moving rays into an object's space and hits back out, with the rounding error carried along
// (pbrt-v4 §6.8.6, "Bounding transformation errors"), so that a hit on a transformed object
// has a world-space error bound a secondary ray can be offset by.
#include <glm/vec3.hpp>

#include <glm/mat4x4.hpp>

#include "collision/bounds3.hpp"
#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "raytracer/geometry/surface_hit.hpp"
#include "raytracer/geometry/transform.hpp"

namespace sweeptrace {

// A world ray in object space. The direction is transformed without renormalising, so a point
// at object parameter s is the world point at t = s + t_shift.
struct ObjectRay {
    collision::Ray ray;
    float t_shift = 0.0f;
};

// The transformed origin is uncertain by its rounding error; like pbrt-v4's
// Transform::ApplyInverse(Ray), the origin is moved forward along the direction to the far edge
// of that error box (by t_shift) so a ray leaving a surface does not start behind it in object
// space. The world interval (tmin, tmax) maps to (tmin - t_shift, tmax - t_shift), except that a
// non-negative tmin stays non-negative (the skipped stretch is the uncertain one).
// The identity transform returns the ray unchanged with t_shift = 0.
ObjectRay to_object_space(const Transform& xf, const collision::Ray& world);

// p, exact within per-axis error `error`, mapped to world: result and its error bound
// (pbrt-v4's Transform of a Point3fi). The affine product is evaluated as
// (m0 x + m1 y) + (m2 z + m3), three roundings per term, so
//   error_w = (1 + gamma(3)) |M3| error + gamma(3) (|M3| |p| + |m3|)
// with |M3| the absolute linear part and m3 the translation.
void point_to_world(const Transform& xf, const glm::vec3& p, const glm::vec3& error, glm::vec3& world_point,
                    glm::vec3& world_error);

// The same for any affine map m (not only an object's transform: a light folds an ellipsoid's
// radii into its map), with the same evaluation order and bound.
void affine_point_to_world(const glm::mat4& m, const glm::vec3& p, const glm::vec3& error, glm::vec3& world_point,
                           glm::vec3& world_error);

// The object-space box mapped to world: the 8 transformed corners, each padded by its
// transformation error bound (point_to_world), so the result holds the exact image of the box.
collision::Bounds3 world_bounds(const Transform& xf, const collision::Bounds3& object_box);

// The object-space hit `h` of the ray `to_object_space` made, as a world SurfaceHit: t, point
// and its error, unit geometric normal by the inverse transpose, uv. The shading normal is set
// to the geometric one (meshes with vertex normals overwrite it). object / primitive are left
// to the caller.
void surface_hit_to_world(const Transform& xf, const collision::RayHit& h, float t_shift, SurfaceHit& out);

}  // namespace sweeptrace

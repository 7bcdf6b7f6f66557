#pragma once
// One object against a world ray: the ray goes into object space, the shape's collision test
// runs there, and the hit comes back with its world-space error bound (object_space.hpp).
// The acceleration structures call this for analytic shapes; for meshes they traverse their
// own bottom-level BVH and finish the hit with mesh_hit_to_world. Here a mesh is tested
// triangle by triangle: the brute-force reference the structures are checked against.
#include <cstdint>

#include "collision/hit.hpp"
#include "collision/ray.hpp"
#include "raytracer/geometry/surface_hit.hpp"
#include <variant>
#include <vector>

#include "raytracer/geometry/object.hpp"

namespace sweeptrace {

// Nearest hit of objects[object] (its mesh, if any, in `meshes`) with world_ray.tmin < t <
// world_ray.tmax; writes `hit` (object and primitive included) only when found. Takes the two
// lists a scene holds, not the scene: geometry sits below the scene in the layering.
bool intersect_object(const std::vector<Object>& objects, const std::vector<Mesh>& meshes, std::uint32_t object,
                      const collision::Ray& world_ray, SurfaceHit& hit);

// The same at shutter fraction `time` (motion.hpp): a moving object in its pose then, a still
// one as above.
bool intersect_object_at(const std::vector<Object>& objects, const std::vector<Mesh>& meshes, std::uint32_t object,
                         const collision::Ray& world_ray, float time, SurfaceHit& hit);

// The swept path of motion blur (issue 25's "ray vs moving sphere in the ray's frame"): a
// sphere moving from one pure translation to another (two keys, no linear part) is, at any
// time, the world sphere centred at its centre plus the translation then (its one rounding,
// monotone, keeps the centre between the keys' centres, so the BVH's boxes hold it). The ray meets that sphere directly, as a still
// untransformed sphere (collision/intersect_sphere.cpp's bound): no pose is built and the ray
// is not mapped. Measured in docs/motion-blur.md; used wherever it applies.
struct SweptSphere {
    collision::Sphere sphere{glm::vec3(0.0f), 0.0f};  // object-space centre and radius; radius 0: not one
    glm::dvec3 from{0.0}, by{0.0};                    // the translation at shutter open, and its change to close
    // The world sphere at shutter fraction `time` (clamped to [0, 1]): the centre plus the
    // translation pose_at interpolates (in double, rounded once).
    collision::Sphere at(float time) const {
        const double f = time > 0.0f ? (time < 1.0f ? static_cast<double>(time) : 1.0) : 0.0;
        return collision::Sphere{sphere.center + glm::vec3(from + f * by), sphere.radius};
    }
};
// The object as a swept sphere when it is one (a sphere, two keys, each a pure translation),
// otherwise radius 0.
SweptSphere swept_sphere(const Object& object);

// The transform an object is seen through at `time`: its own, or its pose then when it moves.
inline Transform object_transform_at(const Object& object, float time) {
    return object.motion.moving() ? pose_at(object.motion, time) : object.transform;
}

// The object-space hit `h` on triangle `triangle` of `mesh`, instanced by `object`, as a world
// SurfaceHit: what surface_hit_to_world gives, plus the shading normal interpolated from the
// mesh's vertex normals (when it has them; turned into the geometric normal's hemisphere).
void mesh_hit_to_world(const Mesh& mesh, const Object& object, std::uint32_t object_index, std::uint32_t triangle,
                       const collision::RayHit& h, float t_shift, SurfaceHit& hit);
// The same through `xf`, the object's pose at the ray's time.
void mesh_hit_to_world(const Mesh& mesh, const Transform& xf, std::uint32_t object_index, std::uint32_t triangle,
                       const collision::RayHit& h, float t_shift, SurfaceHit& hit);

}  // namespace sweeptrace

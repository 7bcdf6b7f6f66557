#pragma once
// One top-level candidate object against a world ray, dispatched by one switch on the shape's
// variant index (no std::visit, no virtual call per candidate): the analytic shape's collision
// test in object space, its hit brought back to world by geometry/object_space. Mesh instances
// are the caller's (they traverse their own wide tree). A shape added to the Shape variant and
// not listed here still works, through geometry's intersect_object.
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <variant>

#include "collision/intersect.hpp"
#include "raytracer/geometry/intersect_object.hpp"
#include "raytracer/geometry/object_space.hpp"

namespace sweeptrace {

// The index of T among a variant's alternatives, as a constant for `case`.
template <class T, class V>
struct shape_tag;
template <class T, class... Ts>
struct shape_tag<T, std::variant<Ts...>> {
    static constexpr std::size_t value = [] {
        std::size_t i = 0;
        ((std::is_same_v<T, Ts> ? false : (++i, true)) && ...);
        return i;
    }();
};
template <class T>
inline constexpr std::size_t shape_tag_v = shape_tag<T, Shape>::value;

template <class S>
inline bool intersect_analytic(const Object& object, std::uint32_t index, const collision::Ray& ray, SurfaceHit& hit) {
    const ObjectRay local = to_object_space(object.transform, ray);
    collision::RayHit h;
    if (!collision::intersect(local.ray, *std::get_if<S>(&object.shape), h)) return false;
    surface_hit_to_world(object.transform, h, local.t_shift, hit);
    hit.object = index;
    hit.primitive = 0;
    return true;
}

// Nearest hit of an analytic object (not a mesh instance) within (ray.tmin, ray.tmax).
inline bool intersect_analytic_object(const Scene& scene, std::uint32_t index, const collision::Ray& ray, SurfaceHit& hit) {
    const Object& object = scene.objects[index];
    switch (object.shape.index()) {
        case shape_tag_v<collision::Sphere>: return intersect_analytic<collision::Sphere>(object, index, ray, hit);
        case shape_tag_v<collision::Aabb>: return intersect_analytic<collision::Aabb>(object, index, ray, hit);
        case shape_tag_v<collision::Cylinder>: return intersect_analytic<collision::Cylinder>(object, index, ray, hit);
        case shape_tag_v<collision::Capsule>: return intersect_analytic<collision::Capsule>(object, index, ray, hit);
        case shape_tag_v<collision::Ellipsoid>: return intersect_analytic<collision::Ellipsoid>(object, index, ray, hit);
        case shape_tag_v<collision::Disk>: return intersect_analytic<collision::Disk>(object, index, ray, hit);
        case shape_tag_v<collision::Quad>: return intersect_analytic<collision::Quad>(object, index, ray, hit);
        case shape_tag_v<collision::Triangle>: return intersect_analytic<collision::Triangle>(object, index, ray, hit);
        default: return intersect_object(scene, index, ray, hit);
    }
}

}  // namespace sweeptrace

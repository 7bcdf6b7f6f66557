#pragma once
// One top-level candidate object against a world ray, dispatched by one indexed call on the shape's
// variant index (no std::visit, no virtual call per candidate; the table is built from
// geometry/shape.hpp's, so a new shape needs nothing here): the analytic shape's collision test in
// object space, its hit brought back to world by geometry/object_space. Mesh instances are the
// caller's (they traverse their own wide tree).
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <variant>

#include "collision/intersect.hpp"
#include "raytracer/geometry/intersect_object.hpp"
#include "raytracer/geometry/object_space.hpp"
#include "raytracer/geometry/shape.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace {

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

// Per shape kind, in the variant's order (geometry/shape.hpp's table): the analytic test, or for a
// mesh instance geometry's brute-force reference (the callers traverse meshes themselves).
using AnalyticTest = bool (*)(const Scene&, std::uint32_t, const collision::Ray&, SurfaceHit&);
template <class Home>
bool intersect_candidate(const Scene& scene, std::uint32_t index, const collision::Ray& ray, SurfaceHit& hit) {
    using G = typename Home::Geometry;
    if constexpr (std::is_same_v<G, MeshInstance>) {
        return intersect_object(scene.objects, scene.meshes, index, ray, hit);
    } else {
        return intersect_analytic<G>(scene.objects[index], index, ray, hit);
    }
}
inline constexpr auto kAnalyticTests =
    Shapes::make_table([](auto home) -> AnalyticTest { return &intersect_candidate<decltype(home)>; });

// Nearest hit of an analytic object (not a mesh instance) within (ray.tmin, ray.tmax).
inline bool intersect_analytic_object(const Scene& scene, std::uint32_t index, const collision::Ray& ray, SurfaceHit& hit) {
    return kAnalyticTests[scene.objects[index].shape.index()](scene, index, ray, hit);
}

}  // namespace sweeptrace

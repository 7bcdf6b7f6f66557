#pragma once
// Every shape the renderer knows, in one table. A shape's renderer-side knowledge lives in its
// home, geometry/shapes/<shape>.{hpp,cpp}: its scene type name and keys, object-space bounds,
// and how it is sampled as a light; its ray test is the collision::intersect overload for its
// geometry (collision/intersect_<shape>.cpp). Everything that depends on the kind of shape (the
// scene loader, the acceleration structures' bounds, the light sampler) dispatches through
// visit_shape below, once, into the home.
//
// Adding a shape: write its home in shapes/ (and its collision::intersect overload), then add
// it to the table below. Nothing else names shapes.
#include <array>
#include <string_view>
#include <type_traits>
#include <variant>

#include "collision/bounds3.hpp"
#include "raytracer/geometry/shapes/box.hpp"
#include "raytracer/geometry/shapes/capsule.hpp"
#include "raytracer/geometry/shapes/cylinder.hpp"
#include "raytracer/geometry/shapes/disk.hpp"
#include "raytracer/geometry/shapes/ellipsoid.hpp"
#include "raytracer/geometry/shapes/mesh_instance.hpp"
#include "raytracer/geometry/shapes/quad.hpp"
#include "raytracer/geometry/shapes/sphere.hpp"
#include "raytracer/geometry/shapes/triangle.hpp"

namespace sweeptrace {

template <ShapeHome... Homes>
struct ShapeTable {
    using Variant = std::variant<typename Homes::Geometry...>;

    // f(Home{}) for every home, in table order.
    template <class F>
    static void for_each_home(F&& f) {
        (f(Homes{}), ...);
    }

    template <class G, class... Rest>
    struct Find {
        using type = void;
    };
    template <class G, class H, class... Rest>
    struct Find<G, H, Rest...> {
        using type = std::conditional_t<std::is_same_v<G, typename H::Geometry>, H, typename Find<G, Rest...>::type>;
    };
    template <class G>
    using HomeOf = typename Find<G, Homes...>::type;

    // {f(Home{})...} in table order, i.e. indexed like the variant's alternatives: a
    // compile-time dispatch table (e.g. of function pointers) that names no shape itself.
    template <class F>
    static constexpr auto make_table(F f) {
        return std::array{f(Homes{})...};
    }
};

// The table: one line per shape.
using Shapes = ShapeTable<SphereShape,
                          BoxShape,
                          CylinderShape,
                          CapsuleShape,
                          EllipsoidShape,
                          DiskShape,
                          QuadShape,
                          TriangleShape,
                          MeshInstanceShape>;

using Shape = Shapes::Variant;

// f(Home{}, geometry) for the shape's alternative: the one dispatch on the kind of shape.
template <class F>
decltype(auto) visit_shape(const Shape& shape, F&& f) {
    return std::visit(
        [&](const auto& geometry) -> decltype(auto) {
            using Home = Shapes::HomeOf<std::decay_t<decltype(geometry)>>;
            return f(Home{}, geometry);
        },
        shape);
}

// Box of the shape in its object space, each bound rounded outward so it holds the exact shape.
// A mesh instance is not analytic: empty (the caller boxes it by its mesh's own BVH).
inline collision::Bounds3 object_space_bounds(const Shape& shape) {
    return visit_shape(shape, [](auto home, const auto& g) { return decltype(home)::object_bounds(g); });
}

// The shape's type name in scene files ("sphere", "mesh", ...).
inline std::string_view shape_type_name(const Shape& shape) {
    return visit_shape(shape, [](auto home, const auto&) { return decltype(home)::kType; });
}

}  // namespace sweeptrace

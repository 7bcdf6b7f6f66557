#include "raytracer/accel/object_bounds.hpp"

#include <cmath>
#include <type_traits>
#include <variant>

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"
#include "raytracer/geometry/object_space.hpp"

namespace sweeptrace {
namespace {

using collision::Bounds3;
using collision::next_float_down;
using collision::next_float_up;

// center +- half, rounded outward: center - half is rounded to nearest, so one step down
// brings it to or below the exact value (and likewise up).
Bounds3 centred(const glm::vec3& center, const glm::vec3& half) {
    Bounds3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = next_float_down(center[a] - half[a]);
        b.hi[a] = next_float_up(center[a] + half[a]);
    }
    return b;
}

// Box of points each computed with at most two additions from values of magnitude <= m:
// padded by gamma(2) m per axis.
Bounds3 padded(const Bounds3& b, const glm::vec3& m) {
    return Bounds3{b.lo - collision::gamma(2) * m, b.hi + collision::gamma(2) * m};
}

}  // namespace

Bounds3 object_space_bounds(const Shape& shape) {
    return std::visit(
        [](const auto& s) -> Bounds3 {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, collision::Sphere>) {
                return centred(s.center, glm::vec3(s.radius));
            } else if constexpr (std::is_same_v<S, collision::Aabb>) {
                return centred(s.center, 0.5f * s.size);  // halving is exact
            } else if constexpr (std::is_same_v<S, collision::Cylinder>) {
                return centred(s.center, glm::vec3(s.radius, 0.5f * s.height, s.radius));
            } else if constexpr (std::is_same_v<S, collision::Capsule>) {
                // 0.5 h + r rounds once; one more outward step covers it.
                return centred(s.center, glm::vec3(s.radius, next_float_up(0.5f * s.height + s.radius), s.radius));
            } else if constexpr (std::is_same_v<S, collision::Ellipsoid>) {
                return centred(s.center, s.radii);
            } else if constexpr (std::is_same_v<S, collision::Disk>) {
                // A disk's extent along axis a is r sqrt(1 - n_a^2) for unit n; the computed value
                // is enlarged by a relative gamma(4) (square, subtraction, sqrt, product) plus one
                // ulp of r for n_a = 1 exactly, where it may round to 0 a touch early.
                glm::vec3 half;
                const glm::vec3 n = glm::normalize(s.normal);
                for (int a = 0; a < 3; ++a) {
                    const float e = s.radius * std::sqrt(std::fmax(0.0f, 1.0f - n[a] * n[a]));
                    half[a] = e * (1.0f + collision::gamma(4)) + s.radius * collision::gamma(2);
                }
                return centred(s.center, half);
            } else if constexpr (std::is_same_v<S, collision::Quad>) {
                Bounds3 b;
                b.extend(s.corner);
                b.extend(s.corner + s.edge_u);
                b.extend(s.corner + s.edge_v);
                b.extend(s.corner + s.edge_u + s.edge_v);
                return padded(b, glm::abs(s.corner) + glm::abs(s.edge_u) + glm::abs(s.edge_v));
            } else if constexpr (std::is_same_v<S, collision::Triangle>) {
                Bounds3 b;  // vertices are exact: min/max of them is the exact box
                b.extend(s.a);
                b.extend(s.b);
                b.extend(s.c);
                return b;
            } else {
                return Bounds3{};
            }
        },
        shape);
}

Bounds3 world_bounds(const Transform& xf, const Bounds3& object_box) {
    if (xf.identity || object_box.empty()) return object_box;
    Bounds3 out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? object_box.hi.x : object_box.lo.x, (corner & 2) ? object_box.hi.y : object_box.lo.y,
                          (corner & 4) ? object_box.hi.z : object_box.lo.z);
        glm::vec3 w, err;
        point_to_world(xf, p, glm::vec3(0.0f), w, err);
        out.extend(w - err);
        out.extend(w + err);
    }
    // w - err and w + err round too: one more outward step.
    for (int a = 0; a < 3; ++a) {
        out.lo[a] = next_float_down(out.lo[a]);
        out.hi[a] = next_float_up(out.hi[a]);
    }
    return out;
}

}  // namespace sweeptrace

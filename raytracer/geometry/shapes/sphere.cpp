#include "raytracer/geometry/shapes/sphere.hpp"

#include <cmath>
#include <limits>

#include <glm/matrix.hpp>

#include "raytracer/geometry/shapes/rounded_bounds.hpp"
#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {
namespace {

using collision::gamma;

// Is the linear part s * R (R orthogonal)? L^T L must then be s^2 I. Each entry of the float
// product carries a few ulps of error relative to s^2, and transforms composed from rotations in
// float carry a few more; 64 ulps accepts those and still rejects any deliberate non-uniform
// scale. A shape accepted with a residual of that size is sampled with a cone off by a relative
// 1e-5, far below noise.
bool is_similarity(const glm::mat3& l, float& scale) {
    const glm::mat3 g = glm::transpose(l) * l;
    const float s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0f;
    const float tol = 64.0f * std::numeric_limits<float>::epsilon() * s2;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(g[c][r] - (c == r ? s2 : 0.0f)) > tol) return false;
    scale = std::sqrt(s2);
    return true;
}

}  // namespace

collision::Bounds3 SphereShape::object_bounds(const Geometry& s) { return centred_bounds(s.center, glm::vec3(s.radius)); }

ShapeLight SphereShape::light(const Geometry& s, const Transform& xf, const std::vector<Mesh>&) {
    ShapeLight l = object_space_light(xf, ShapeLight::Strategy::ObjectArea);
    float scale = 1.0f;
    if (is_similarity(l.linear, scale)) {
        l.strategy = ShapeLight::Strategy::SphereCone;
        l.origin = transform_point(xf.to_world, s.center);
        l.radius = scale * s.radius;
        l.area = 4.0f * kPi * l.radius * l.radius;
        l.area_pdf = 1.0f / l.area;
    } else {
        const float object_area = 4.0f * kPi * s.radius * s.radius;
        l.area_pdf = 1.0f / object_area;
        l.area = object_area_stand_in(object_area, l.inv_abs_det);
    }
    return l;
}


}  // namespace sweeptrace

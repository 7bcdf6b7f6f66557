#include "raytracer/geometry/shapes/mesh_instance.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"
#include "raytracer/geometry/warps.hpp"

namespace sweeptrace {

using collision::gamma;

ShapeLight MeshInstanceShape::light(const Geometry& m, const Transform& xf, const std::vector<Mesh>& meshes) {
    ShapeLight l = object_space_light(xf, ShapeLight::Strategy::MeshArea);
    const collision::TriangleMesh& tm = meshes[m.mesh].triangles;
    l.mesh = &tm;
    l.triangle_cdf.reserve(tm.triangle_count());
    double sum = 0.0;
    for (std::size_t k = 0; k < tm.triangle_count(); ++k) {
        const collision::Triangle tri = tm.triangle(k);
        sum += 0.5 * glm::length(glm::cross(l.linear * (tri.b - tri.a), l.linear * (tri.c - tri.a)));
        l.triangle_cdf.push_back(static_cast<float>(sum));
    }
    l.area = static_cast<float>(sum);
    l.area_pdf = 1.0f / l.area;
    return l;
}

void MeshInstanceShape::sample(const Geometry&, const ShapeLight& l, float u_part, float u1, float u2, SurfacePoint& out) {
    const std::vector<float>& cdf = l.triangle_cdf;
    const auto hit = std::upper_bound(cdf.begin(), cdf.end(), u_part * cdf.back());
    const std::size_t k = static_cast<std::size_t>(std::min<std::ptrdiff_t>(hit - cdf.begin(), cdf.size() - 1));
    const collision::Triangle tri = l.mesh->triangle(k);
    const glm::vec2 b = uniform_triangle(u1, u2);
    out.point = b.x * tri.a + b.y * tri.b + (1.0f - b.x - b.y) * tri.c;
    out.error = gamma(4) * (glm::abs(tri.a) + glm::abs(tri.b) + glm::abs(tri.c));
    out.normal = glm::cross(tri.b - tri.a, tri.c - tri.a);
}

}  // namespace sweeptrace

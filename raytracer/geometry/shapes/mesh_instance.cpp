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
    out.primitive = static_cast<std::uint32_t>(k);
}

glm::vec2 MeshInstanceShape::mesh_uv(const Geometry& m, const std::vector<Mesh>& meshes, std::uint32_t primitive,
                                     const glm::vec3& p) {
    const Mesh& mesh = meshes[m.mesh];
    if (mesh.vertex_uvs.empty() || primitive >= mesh.triangles.indices.size()) return glm::vec2(0.0f);
    const glm::uvec3 f = mesh.triangles.indices[primitive];
    const glm::vec3 a = mesh.triangles.vertices[f.x];
    // Barycentrics (b1, b2) of p by the dual basis of the edges, as the triangle's own home does.
    const glm::vec3 e1 = mesh.triangles.vertices[f.y] - a, e2 = mesh.triangles.vertices[f.z] - a, d = p - a;
    const glm::vec3 n = glm::cross(e1, e2);
    const float nn = glm::dot(n, n);
    if (!(nn > 0.0f)) return mesh.vertex_uvs[f.x];
    const float b1 = glm::dot(glm::cross(d, e2), n) / nn, b2 = glm::dot(glm::cross(e1, d), n) / nn;
    return (1.0f - b1 - b2) * mesh.vertex_uvs[f.x] + b1 * mesh.vertex_uvs[f.y] + b2 * mesh.vertex_uvs[f.z];
}

UvTangents MeshInstanceShape::mesh_uv_tangents(const Geometry& m, const std::vector<Mesh>& meshes,
                                               std::uint32_t primitive) {
    const Mesh& mesh = meshes[m.mesh];
    if (mesh.vertex_uvs.empty() || primitive >= mesh.triangles.indices.size()) return {};
    const glm::uvec3 f = mesh.triangles.indices[primitive];
    const glm::vec3 p0 = mesh.triangles.vertices[f.x];
    const glm::vec3 e1 = mesh.triangles.vertices[f.y] - p0, e2 = mesh.triangles.vertices[f.z] - p0;
    const glm::vec2 t0 = mesh.vertex_uvs[f.x];
    const glm::vec2 d1 = mesh.vertex_uvs[f.y] - t0, d2 = mesh.vertex_uvs[f.z] - t0;
    // e1 = dpdu d1.x + dpdv d1.y and e2 likewise: solved by Cramer's rule.
    const float det = d1.x * d2.y - d1.y * d2.x;
    if (!(std::abs(det) > 0.0f)) return {};
    return {(d2.y * e1 - d1.y * e2) / det, (d1.x * e2 - d2.x * e1) / det};
}

}  // namespace sweeptrace

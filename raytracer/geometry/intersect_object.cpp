#include "raytracer/geometry/intersect_object.hpp"

#include <cmath>
#include <type_traits>
#include <variant>

#include <glm/geometric.hpp>

#include "collision/intersect.hpp"
#include "raytracer/geometry/object_space.hpp"

namespace sweeptrace {

void mesh_hit_to_world(const Mesh& mesh, const Object& object, std::uint32_t object_index, std::uint32_t triangle,
                       const collision::RayHit& h, float t_shift, SurfaceHit& hit) {
    mesh_hit_to_world(mesh, object.transform, object_index, triangle, h, t_shift, hit);
}

void mesh_hit_to_world(const Mesh& mesh, const Transform& xf, std::uint32_t object_index, std::uint32_t triangle,
                       const collision::RayHit& h, float t_shift, SurfaceHit& hit) {
    surface_hit_to_world(xf, h, t_shift, hit);
    hit.object = object_index;
    hit.primitive = triangle;
    if (mesh.vertex_normals.empty()) return;
    const glm::uvec3& f = mesh.triangles.indices[triangle];
    const float b1 = h.uv.x, b2 = h.uv.y, b0 = 1.0f - b1 - b2;
    glm::vec3 ns = b0 * mesh.vertex_normals[f.x] + b1 * mesh.vertex_normals[f.y] + b2 * mesh.vertex_normals[f.z];
    if (!xf.identity) ns = xf.normal_to_world * ns;
    const float len2 = glm::dot(ns, ns);
    // Opposite vertex normals can cancel; the geometric normal stays then.
    if (!(len2 > 0.0f) || !std::isfinite(len2)) return;
    ns /= std::sqrt(len2);
    hit.shading_normal = glm::dot(ns, hit.normal) < 0.0f ? -ns : ns;
}

namespace {

bool intersect_through(const std::vector<Object>& objects, const std::vector<Mesh>& meshes, std::uint32_t object_index,
                       const Transform& xf, const collision::Ray& world_ray, SurfaceHit& hit) {
    const Object& object = objects[object_index];
    const ObjectRay local = to_object_space(xf, world_ray);
    return std::visit(
        [&](const auto& shape) {
            using S = std::decay_t<decltype(shape)>;
            collision::RayHit h;
            if constexpr (std::is_same_v<S, MeshInstance>) {
                const Mesh& mesh = meshes[shape.mesh];
                collision::Ray ray = local.ray;
                std::uint32_t nearest = 0;
                bool found = false;
                for (std::size_t i = 0; i < mesh.triangles.triangle_count(); ++i) {
                    if (collision::intersect(ray, mesh.triangles.triangle(i), h)) {
                        ray.tmax = h.t;
                        nearest = static_cast<std::uint32_t>(i);
                        found = true;
                    }
                }
                if (!found) return false;
                mesh_hit_to_world(mesh, xf, object_index, nearest, h, local.t_shift, hit);
                return true;
            } else {
                if (!collision::intersect(local.ray, shape, h)) return false;
                surface_hit_to_world(xf, h, local.t_shift, hit);
                hit.object = object_index;
                hit.primitive = 0;
                return true;
            }
        },
        object.shape);
}

}  // namespace

bool intersect_object(const std::vector<Object>& objects, const std::vector<Mesh>& meshes, std::uint32_t object_index,
                      const collision::Ray& world_ray, SurfaceHit& hit) {
    return intersect_through(objects, meshes, object_index, objects[object_index].transform, world_ray, hit);
}

SweptSphere swept_sphere(const Object& object) {
    SweptSphere out;
    const Motion& m = object.motion;
    const auto* sphere = std::get_if<collision::Sphere>(&object.shape);
    if (!sphere || !m.moving() || !m.translation_only || m.keys.size() != 2) return out;
    const glm::mat4& w = m.keys[0].to_world;
    if (glm::vec3(w[0]) != glm::vec3(1, 0, 0) || glm::vec3(w[1]) != glm::vec3(0, 1, 0) || glm::vec3(w[2]) != glm::vec3(0, 0, 1))
        return out;
    out.sphere = *sphere;
    out.from = m.parts[0].translation;
    out.by = m.parts[1].translation - m.parts[0].translation;
    return out;
}

bool intersect_object_at(const std::vector<Object>& objects, const std::vector<Mesh>& meshes, std::uint32_t object_index,
                         const collision::Ray& world_ray, float time, SurfaceHit& hit) {
    const Object& object = objects[object_index];
    if (!object.motion.moving()) return intersect_through(objects, meshes, object_index, object.transform, world_ray, hit);
    if (const SweptSphere swept = swept_sphere(object); swept.sphere.radius > 0.0f) {
        collision::RayHit h;
        if (!collision::intersect(world_ray, swept.at(time), h)) return false;
        surface_hit_to_world(Transform{}, h, 0.0f, hit);
        hit.object = object_index;
        hit.primitive = 0;
        return true;
    }
    return intersect_through(objects, meshes, object_index, pose_at(object.motion, time), world_ray, hit);
}

}  // namespace sweeptrace

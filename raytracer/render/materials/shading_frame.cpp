#include "raytracer/render/materials/shading_frame.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace sweeptrace {

UvTangents hit_uv_tangents(const Scene& scene, const SurfaceHit& hit) {
    const Object& obj = scene.objects[hit.object];
    const glm::vec3 p(obj.transform.to_object * glm::vec4(hit.point, 1.0f));
    const UvTangents local = visit_shape(obj.shape, [&](auto home, const auto& g) -> UvTangents {
        using Home = decltype(home);
        if constexpr (requires { Home::uv_tangents(g, p); }) return Home::uv_tangents(g, p);
        else if constexpr (requires { Home::mesh_uv_tangents(g, scene.meshes, hit.primitive); })
            return Home::mesh_uv_tangents(g, scene.meshes, hit.primitive);
        else return UvTangents{};
    });
    if (obj.transform.identity) return local;
    const glm::mat3 linear(obj.transform.to_world);
    return {linear * local.dpdu, linear * local.dpdv};
}

namespace {

// v's part orthogonal to the unit normal n: a tangent of the shading frame.
glm::vec3 along_surface(const glm::vec3& v, const glm::vec3& n) { return v - n * glm::dot(n, v); }

// `n` normalised, or `ns` where it is degenerate or would turn the shading normal to or below
// the geometric plane (the guards in the header).
glm::vec3 guarded(const glm::vec3& n, const glm::vec3& ns, const glm::vec3& ng) {
    const float nn = glm::dot(n, n);
    if (!(nn > 0.0f) || !std::isfinite(nn)) return ns;
    const glm::vec3 mapped = n / std::sqrt(nn);
    return glm::dot(mapped, ng) > 0.0f ? mapped : ns;
}

}  // namespace

glm::vec3 normal_from_map(const glm::vec3& ns, const glm::vec3& ng, const UvTangents& t, const glm::vec3& texel) {
    glm::vec3 tangent = along_surface(t.dpdu, ns);
    const float tt = glm::dot(tangent, tangent);
    if (!(tt > 0.0f) || !std::isfinite(tt)) return ns;
    tangent /= std::sqrt(tt);
    glm::vec3 bitangent = glm::cross(ns, tangent);
    if (glm::dot(bitangent, t.dpdv) < 0.0f) bitangent = -bitangent;
    const glm::vec3 m = 2.0f * texel - glm::vec3(1.0f);
    return guarded(m.x * tangent + m.y * bitangent + m.z * ns, ns, ng);
}

glm::vec3 normal_from_bump(const glm::vec3& ns, const glm::vec3& ng, const UvTangents& t, float dh_du, float dh_dv) {
    const glm::vec3 tu = along_surface(t.dpdu, ns), tv = along_surface(t.dpdv, ns);
    const glm::vec3 flat = glm::cross(tu, tv);  // along ns, either way round (a mirrored uv map)
    const float side = glm::dot(flat, ns);
    if (!(std::abs(side) > 0.0f && std::isfinite(side) && std::isfinite(dh_du) && std::isfinite(dh_dv))) return ns;
    // (tu + dh_du ns) x (tv + dh_dv ns), expanded: ns x ns = 0.
    const glm::vec3 n = flat + dh_dv * glm::cross(tu, ns) + dh_du * glm::cross(ns, tv);
    return guarded(side > 0.0f ? n : -n, ns, ng);
}

}  // namespace sweeptrace

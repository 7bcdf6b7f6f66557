#pragma once
// A ray's nearest hit in world space, with the rounding-error bound of its point so that the
// next ray can leave the surface without re-hitting it (pbrt's offset, not a tuned epsilon).
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "collision/ray.hpp"

namespace sweeptrace {

struct SurfaceHit {
    float t = 0.0f;
    glm::vec3 point{0.0f};
    glm::vec3 point_error{0.0f};     // conservative per-axis bound, world space
    glm::vec3 normal{0.0f};          // unit geometric normal, outward (not flipped toward the ray)
    glm::vec3 shading_normal{0.0f};  // unit, same hemisphere as `normal`
    glm::vec2 uv{0.0f};
    std::uint32_t object = 0;        // index into Scene::objects
    std::uint32_t primitive = 0;     // triangle index within a mesh, 0 otherwise
};

// A ray leaving `hit` in direction `dir`, its origin pushed off the surface along the normal
// (toward the side `dir` points to) by the point's error bound, so it cannot re-hit the surface.
collision::Ray spawn_ray(const SurfaceHit& hit, const glm::vec3& dir);

// A shadow ray from `hit` toward `target` (a point on a light, carrying `target_error`, with the
// light's unit geometric normal `target_normal`, either orientation). Both ends are pushed off
// their surfaces by their error bounds (pbrt-v4's SpawnRayTo between two interactions), and the
// ray stops short of the offset target: tmax < 1 along dir = offset target - origin, backed off
// by the intersectors' t error bound there, which grows as the target is seen more grazingly
// (derivation and scope in spawn_ray.cpp).
collision::Ray spawn_ray_to(const SurfaceHit& hit, const glm::vec3& target, const glm::vec3& target_error,
                            const glm::vec3& target_normal);

}  // namespace sweeptrace

#include "raytracer/geometry/object_space.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "collision/float_error.hpp"

namespace sweeptrace {
namespace {

using collision::gamma;

// m * (p, 1) evaluated as (m0 x + m1 y) + (m2 z + m3): three roundings per term.
glm::vec3 apply_affine(const glm::mat4& m, const glm::vec3& p) {
    glm::vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = (m[0][i] * p.x + m[1][i] * p.y) + (m[2][i] * p.z + m[3][i]);
    return r;
}

// |M3| |p| + |m3| per row: the magnitude the rounding of apply_affine is relative to.
glm::vec3 affine_magnitude(const glm::mat4& m, const glm::vec3& p) {
    glm::vec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = std::fabs(m[0][i] * p.x) + std::fabs(m[1][i] * p.y) + std::fabs(m[2][i] * p.z) + std::fabs(m[3][i]);
    return r;
}

glm::vec3 apply_linear(const glm::mat4& m, const glm::vec3& d) {
    glm::vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = (m[0][i] * d.x + m[1][i] * d.y) + m[2][i] * d.z;
    return r;
}

}  // namespace

ObjectRay to_object_space(const Transform& xf, const collision::Ray& world) {
    if (xf.identity) return ObjectRay{world, 0.0f};
    ObjectRay out;
    const glm::vec3 o = apply_affine(xf.to_object, world.origin);
    const glm::vec3 d = apply_linear(xf.to_object, world.dir);
    // Error of o: gamma(3) from the evaluation, plus the error of to_object itself against the
    // exact inverse of to_world (Transform::from_matrix inverts in double and rounds once: each
    // entry within machine_epsilon relative), together within gamma(4) of the magnitude. The
    // magnitude is taken of the computed product; the difference is second order.
    const glm::vec3 o_error = gamma(4) * affine_magnitude(xf.to_object, world.origin);
    const float len2 = glm::dot(d, d);
    float shift = 0.0f;
    if (len2 > 0.0f && std::isfinite(len2)) {
        shift = glm::dot(glm::abs(d), o_error) / len2;
        if (!std::isfinite(shift)) shift = 0.0f;
    }
    out.ray.origin = o + d * shift;
    out.ray.dir = d;
    out.ray.tmin = world.tmin >= 0.0f ? std::fmax(world.tmin - shift, 0.0f) : world.tmin - shift;
    out.ray.tmax = world.tmax - shift;
    out.t_shift = shift;
    return out;
}

void point_to_world(const Transform& xf, const glm::vec3& p, const glm::vec3& error, glm::vec3& world_point,
                    glm::vec3& world_error) {
    if (xf.identity) {
        world_point = p;
        world_error = error;
        return;
    }
    affine_point_to_world(xf.to_world, p, error, world_point, world_error);
}

void affine_point_to_world(const glm::mat4& m, const glm::vec3& p, const glm::vec3& error, glm::vec3& world_point,
                           glm::vec3& world_error) {
    world_point = apply_affine(m, p);
    const glm::vec3 propagated =
        glm::abs(glm::vec3(m[0])) * error.x + glm::abs(glm::vec3(m[1])) * error.y + glm::abs(glm::vec3(m[2])) * error.z;
    world_error = (1.0f + gamma(3)) * propagated + gamma(3) * affine_magnitude(m, p);
}

collision::Bounds3 world_bounds(const Transform& xf, const collision::Bounds3& object_box) {
    if (xf.identity || object_box.empty()) return object_box;
    collision::Bounds3 out;
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
        out.lo[a] = collision::next_float_down(out.lo[a]);
        out.hi[a] = collision::next_float_up(out.hi[a]);
    }
    return out;
}

void surface_hit_to_world(const Transform& xf, const collision::RayHit& h, float t_shift, SurfaceHit& out) {
    out.t = h.t + t_shift;
    out.uv = h.uv;
    point_to_world(xf, h.point, h.point_error, out.point, out.point_error);
    out.normal = xf.identity ? h.normal : glm::normalize(xf.normal_to_world * h.normal);
    out.shading_normal = out.normal;
}

}  // namespace sweeptrace

#include "raytracer/render/media/media_nesting.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>

#include "raytracer/geometry/intersect_object.hpp"
#include "raytracer/geometry/object_world_bounds.hpp"
#include "raytracer/input_error.hpp"

namespace sweeptrace {

namespace {

const std::array<glm::vec3, 6> kAxes{glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                                     glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)};
// The directions of an object's probes: (+-1, +-2, +-3), one per octant. Not the axes: through
// the box's centre they meet a shape at its extremes, where it rests on or touches another (a
// sphere on a floor, a sliver of it through a fog box's bottom) rather than where it bounds its
// media; nor the diagonals, which meet a box at its corners.
std::array<glm::vec3, 8> probe_directions() {
    std::array<glm::vec3, 8> d{};
    for (int k = 0; k < 8; ++k)
        d[static_cast<std::size_t>(k)] = glm::vec3(k & 1 ? -1.0f : 1.0f, k & 2 ? -2.0f : 2.0f, k & 4 ? -3.0f : 3.0f);
    return d;
}

std::string medium_text(const Scene& scene, std::int32_t m) {
    if (m < 0) return "vacuum";
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "\"" + name + "\"" here.
    std::string s = "\"";
    s += excerpt(scene.media[static_cast<std::size_t>(m)].name);
    s += '"';
    return s;
}

std::string point_text(const glm::vec3& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", double(p.x), double(p.y), double(p.z));
    return buf;
}

// What the first surface along `ray` says about the medium the ray is in before it: its object
// when that is a boundary (and the medium on the side the ray arrives from), nothing otherwise.
struct Verdict {
    bool found = false;
    std::uint32_t object = 0;
    std::int32_t medium = -1;
};

Verdict first_boundary(const Scene& scene, const Accel& accel, const collision::Ray& ray) {
    SurfaceHit hit;
    if (!accel.intersect(ray, hit)) return {};
    const MediumInterface& mi = scene.objects[hit.object].media;
    if (!mi.transition()) return {};
    return {true, hit.object, glm::dot(ray.dir, hit.normal) < 0.0f ? mi.outside : mi.inside};
}

[[noreturn]] void mismatch(const Scene& scene, const std::string& who, const std::string& along, std::int32_t declared,
                           const Verdict& v) {
    throw InputError(scene.source.filename().string() + ": media do not nest: " + who + " is " +
                     medium_text(scene, declared) + ", but " + along + " the first surface, " +
                     excerpt(scene.objects[v.object].name, 120) + ", has " + medium_text(scene, v.medium) +
                     " on that side");
}

void check_object(const Scene& scene, const Accel& accel, std::uint32_t i) {
    const Object& o = scene.objects[i];
    const collision::Bounds3 box = object_world_bounds(o, scene.meshes);
    if (box.empty()) return;
    const glm::vec3 centre = 0.5f * (box.lo + box.hi);
    // From a whole diagonal away every probe starts outside the box.
    const float reach = glm::length(box.hi - box.lo);
    if (!std::isfinite(reach)) return;
    for (const glm::vec3& d : probe_directions()) {
        SurfaceHit on;
        const glm::vec3 u = glm::normalize(d);
        if (!intersect_object(scene.objects, scene.meshes, i, collision::Ray{centre - u * reach, u}, on)) continue;
        for (const float side : {1.0f, -1.0f}) {
            const Verdict v = first_boundary(scene, accel, spawn_ray(on, side * on.normal));
            const std::int32_t declared = side > 0.0f ? o.media.outside : o.media.inside;
            if (v.found && v.medium != declared)
                mismatch(scene, excerpt(o.name, 120) + "'s \"" + (side > 0.0f ? "outside" : "inside") + "\"",
                         std::string("from its point ") + point_text(on.point) + " along its " +
                             (side > 0.0f ? "outward" : "inward") + " normal",
                         declared, v);
        }
    }
}

void check_camera(const Scene& scene, const Accel& accel) {
    const Camera& c = scene.camera;
    std::array<glm::vec3, 7> dirs{};
    for (std::size_t k = 0; k < kAxes.size(); ++k) dirs[k] = kAxes[k];
    dirs[6] = c.look_at - c.position;
    for (const glm::vec3& d : dirs) {
        if (d == glm::vec3(0.0f)) continue;
        const Verdict v = first_boundary(scene, accel, collision::Ray{c.position, d});
        if (v.found && v.medium != c.medium)
            mismatch(scene, "the camera's \"medium\"", "looking from " + point_text(c.position) + " along " + point_text(d),
                     c.medium, v);
    }
}

}  // namespace

void check_media_nesting(const Scene& scene, const Accel& accel) {
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].media.transition()) check_object(scene, accel, i);
    check_camera(scene, accel);
}

}  // namespace sweeptrace

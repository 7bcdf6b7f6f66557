#include "raytracer/accuracy/motion_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

#include <glm/geometric.hpp>

#include "raytracer/accel/brute_force_accel.hpp"
#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/accel/embree_accel.hpp"
#include "raytracer/accuracy/tessellate.hpp"
#include "raytracer/geometry/motion.hpp"
#include "raytracer/scene/scene_transform.hpp"

namespace sweeptrace::accuracy {
namespace {

Transform key(const glm::dmat4& m) { return Transform::from_matrix(glm::mat4(m)); }

glm::dmat4 turned(double degrees, const glm::dvec3& to) {
    return translation_matrix(to) * rotation_matrix({0.3, 1.0, 0.2}, degrees);
}

struct MovingCase {
    std::string name;
    Shape shape;
    std::vector<glm::dmat4> keys;
};

Scene scene_of(const MovingCase& c, std::vector<Mesh>& meshes) {
    Scene s;
    s.camera.shutter = true;
    s.camera.shutter_close = 1.0f;
    s.materials.push_back(Material{});
    s.meshes = meshes;
    Object o;
    o.shape = c.shape;
    std::vector<Transform> keys;
    for (const glm::dmat4& m : c.keys) keys.push_back(key(m));
    o.transform = keys[0];
    o.motion = make_motion(std::move(keys));
    o.name = c.name;
    s.objects.push_back(std::move(o));
    return s;
}

}  // namespace

std::vector<MotionRow> measure_motion(std::size_t rays, std::uint64_t seed) {
    std::vector<Mesh> meshes{tessellate(collision::Sphere{glm::vec3(0.0f), 0.8f}, 2000)};
    const std::vector<MovingCase> cases = {
        {"sphere, translating 3 sizes (swept path)", collision::Sphere{glm::vec3(0.0f), 0.5f},
         {translation_matrix({-1.5, 0, 0}), translation_matrix({1.5, 0.3, 0})}},
        {"sphere, translating through 3 keys (pose path)", collision::Sphere{glm::vec3(0.0f), 0.5f},
         {translation_matrix({-1.5, 0, 0}), translation_matrix({0, 0.6, 0}), translation_matrix({1.5, 0, 0.2})}},
        {"box, turning 180 degrees in 3 keys", collision::Aabb{glm::vec3(0.0f), glm::vec3(1.6f, 0.4f, 0.6f)},
         {turned(0, {0, 0, 0}), turned(90, {0.2, 0, 0}), turned(180, {0.4, 0, 0})}},
        {"cylinder, stretching and turning", collision::Cylinder{glm::vec3(0.0f), 0.4f, 1.2f},
         {translation_matrix({-0.5, 0, 0}),
          translation_matrix({0.5, 0, 0}) * rotation_matrix({1, 0, 0}, 60) * scale_matrix({1.0, 1.6, 1.0})}},
        {"mesh (2000 triangles), translating", MeshInstance{0},
         {translation_matrix({-1.2, 0, 0}), translation_matrix({1.2, 0, 0.5})}},
        {"mesh (2000 triangles), turning 90 degrees", MeshInstance{0},
         {turned(0, {0, 0, 0}) * scale_matrix({1.5, 0.6, 1.0}), turned(90, {0.5, 0, 0}) * scale_matrix({1.5, 0.6, 1.0})}},
    };
    std::vector<MotionRow> rows;
    for (const MovingCase& c : cases) {
        const Scene scene = scene_of(c, meshes);
        const auto brute = make_brute_force_accel(scene);
        const BvhAccel bvh(scene);
        const auto embree = make_embree_accel(scene);
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<float> u(-1.0f, 1.0f), t01(0.0f, 1.0f);
        MotionRow row;
        row.motion = c.name;
        for (std::size_t i = 0; i < rays; ++i) {
            // From a sphere of radius 6 around the scene toward a point of the swept region.
            glm::vec3 from(u(rng), u(rng), u(rng));
            if (glm::dot(from, from) < 1e-6f) from = glm::vec3(0.0f, 0.0f, 1.0f);
            const glm::vec3 origin = 6.0f * glm::normalize(from);
            const glm::vec3 target(2.0f * u(rng), 1.0f * u(rng), 1.0f * u(rng));
            const collision::Ray ray{origin, glm::normalize(target - origin)};
            const float time = t01(rng);
            SurfaceHit hb, hn, he;
            const bool b = brute->intersect(ray, time, hb);
            const bool n = bvh.intersect(ray, time, hn);
            const bool e = embree->intersect(ray, time, he);
            ++row.rays;
            row.hits += b ? 1 : 0;
            if (n != b || (b && hn.t != hb.t) || bvh.occluded(ray, time) != b) ++row.bvh_differs;
            if (e != b || embree->occluded(ray, time) != b) ++row.embree_differs;
            if (e && b) row.embree_t_max = std::max(row.embree_t_max, double(std::fabs(he.t - hb.t) / hb.t));
        }
        rows.push_back(row);
    }
    return rows;
}

void write_motion_csv(std::ostream& out, const std::vector<MotionRow>& rows) {
    out << "motion,rays,hits,bvh_differs,embree_differs,embree_t_max_relative\n";
    char buf[256];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "\"%s\",%zu,%zu,%zu,%zu,%.3g\n", r.motion.c_str(), r.rays, r.hits, r.bvh_differs,
                      r.embree_differs, r.embree_t_max);
        out << buf;
    }
}

void write_motion_markdown(std::ostream& out, const std::vector<MotionRow>& rows) {
    out << "| moving object | rays | hits | BVH differs from brute force | Embree differs | Embree's largest relative t difference |\n"
           "|---|---:|---:|---:|---:|---:|\n";
    char buf[320];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "| %s | %zu | %zu | %zu | %zu | %.2g |\n", r.motion.c_str(), r.rays, r.hits,
                      r.bvh_differs, r.embree_differs, r.embree_t_max);
        out << buf;
    }
}

}  // namespace sweeptrace::accuracy

// The native BVH and Embree against brute force (every object, every triangle) on seeded random
// rays: same hit or miss, same object and triangle, same t; occluded() agrees with intersect().
#include <catch2/catch.hpp>

#include <memory>
#include <random>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/matrix.hpp>

#include "collision/float_error.hpp"

#include "accel_test_scenes.hpp"
#include "raytracer/accel/brute_force_accel.hpp"
#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/accel/embree_accel.hpp"
#include "raytracer/geometry/object_space.hpp"
#include "raytracer/geometry/object_world_bounds.hpp"
#include "raytracer/geometry/shape.hpp"

using namespace sweeptrace;

namespace {

struct Tally {
    int rays = 0, hits = 0;
};

// Random rays: half from anywhere in the scene's box in any direction, half aimed from outside
// at a random point inside a random object's world box (so small objects get hit too).
std::vector<collision::Ray> random_rays(const Scene& scene, int n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    collision::Bounds3 all;
    std::vector<collision::Bounds3> boxes;
    BvhAccel probe(scene);
    for (const Object& o : scene.objects) {
        collision::Bounds3 local;
        if (const auto* m = std::get_if<MeshInstance>(&o.shape)) {
            for (const glm::vec3& v : scene.meshes[m->mesh].triangles.vertices) local.extend(v);
        } else {
            local = object_space_bounds(o.shape);
        }
        boxes.push_back(world_bounds(o.transform, local));
        all.extend(boxes.back());
    }
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    auto in = [&](const collision::Bounds3& b) {
        return b.lo + glm::vec3(u(rng), u(rng), u(rng)) * (b.hi - b.lo);
    };
    const collision::Bounds3 big{all.lo - 0.5f * (all.hi - all.lo), all.hi + 0.5f * (all.hi - all.lo)};
    std::uniform_int_distribution<std::size_t> pick(0, boxes.size() - 1);
    std::vector<collision::Ray> rays;
    for (int i = 0; i < n; ++i) {
        if (i % 2 == 0) {
            rays.push_back(collision::Ray{in(big), test::random_direction(rng)});
        } else {
            const glm::vec3 target = in(boxes[pick(rng)]);
            const glm::vec3 origin = in(big);
            rays.push_back(collision::Ray{origin, target - origin});
        }
    }
    return rays;
}

void compare(const Scene& scene, const Accel& reference, const Accel& tested, const std::vector<collision::Ray>& rays,
             Tally& tally) {
    for (const collision::Ray& ray : rays) {
        SurfaceHit a, b;
        const bool ha = reference.intersect(ray, a);
        const bool hb = tested.intersect(ray, b);
        ++tally.rays;
        INFO(tested.name() << " ray o=(" << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z << ") d=("
                           << ray.dir.x << "," << ray.dir.y << "," << ray.dir.z << ")");
        REQUIRE(ha == hb);
        REQUIRE(tested.occluded(ray) == hb);
        if (!ha) continue;
        ++tally.hits;
        INFO("object " << a.object << " (" << scene.objects[a.object].name << ") t=" << a.t << " vs object " << b.object
                       << " t=" << b.t);
        REQUIRE(a.object == b.object);
        REQUIRE(a.primitive == b.primitive);
        CHECK(a.t == b.t);
        // Occlusion of the segment up to just before / just after the hit.
        collision::Ray before = ray, after = ray;
        before.tmax = a.t * 0.999f;
        after.tmax = a.t * 1.001f;
        CHECK(tested.occluded(after));
        SurfaceHit nearer;
        CHECK(tested.occluded(before) == tested.intersect(before, nearer));
    }
}

// For a hit on a mesh triangle: t of the ray's crossing of the triangle's plane, in double with
// the exact inverse of to_world, and a bound on a float implementation's |t - t_ref|.
// The float paths round (i) the ray into object space: origin within gamma(4) (|Minv||o| + |m|),
// direction within gamma(3) |Minv||d| (object_space.cpp), and (ii) the triangle test itself,
// whose t error (collision/triangle_watertight.hpp) is at most gamma(7) of the same magnitudes
// (|a - o| per vertex, |t d|) over |n . d|. Embree inverts the instance matrix in float (a few
// roundings more, on transforms with condition < 3 here). gamma(16) covers the sum.
struct TReference {
    double t = 0.0, bound = 0.0;
};
TReference plane_t(const Scene& scene, const SurfaceHit& hit, const collision::Ray& ray) {
    const Object& object = scene.objects[hit.object];
    const Mesh& mesh = scene.meshes[std::get<MeshInstance>(object.shape).mesh];
    const collision::Triangle tri = mesh.triangles.triangle(hit.primitive);
    const glm::dmat4 inv = glm::inverse(glm::dmat4(object.transform.to_world));
    const glm::dvec3 o = glm::dvec3(inv * glm::dvec4(glm::dvec3(ray.origin), 1.0));
    const glm::dvec3 d = glm::dmat3(inv) * glm::dvec3(ray.dir);
    const glm::dvec3 a(tri.a), b(tri.b), c(tri.c);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    TReference r;
    r.t = glm::dot(n, a - o) / glm::dot(n, d);
    const glm::dmat3 abs_inv = glm::dmat3(glm::abs(glm::dvec3(inv[0])), glm::abs(glm::dvec3(inv[1])), glm::abs(glm::dvec3(inv[2])));
    const glm::dvec3 origin_mag = abs_inv * glm::abs(glm::dvec3(ray.origin)) + glm::abs(glm::dvec3(inv[3]));
    const glm::dvec3 dir_mag = abs_inv * glm::abs(glm::dvec3(ray.dir));
    const glm::dvec3 vertex_mag = glm::max(glm::abs(a - o), glm::max(glm::abs(b - o), glm::abs(c - o)));
    const glm::dvec3 an = glm::abs(n);
    r.bound = collision::gamma(16) *
              (glm::dot(an, origin_mag + vertex_mag) + std::abs(r.t) * glm::dot(an, dir_mag)) / std::abs(glm::dot(n, d));
    return r;
}

}  // namespace

TEST_CASE("accel: the native BVH finds exactly what brute force finds", "[accel]") {
    Tally tally;
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        const Scene scene = seed == 3 ? test::mesh_scene(seed) : test::mixed_scene(seed, seed == 2 ? 3.0f : 10.0f);
        const auto brute = make_brute_force_accel(scene);
        const BvhAccel bvh(scene);
        compare(scene, *brute, bvh, random_rays(scene, seed == 3 ? 800 : 2000, seed), tally);
    }
    CHECK(tally.hits > tally.rays / 4);  // the rays do exercise hits
}

TEST_CASE("accel: a direction component of -0 is traversed as +0 is (the slab's near face by the sign bit)", "[accel]") {
    // Axis-parallel rays whose zero components are -0, as negating an axis-aligned normal makes
    // them. The native BVH picked each box's near face by `dir < 0` but divided by -0 into -inf,
    // and missed every box (found by the media nesting check: an inward probe from a fog box's
    // face met nothing).
    Tally tally;
    for (std::uint32_t seed : {1u, 3u}) {
        const Scene scene = seed == 3 ? test::mesh_scene(seed) : test::mixed_scene(seed);
        const auto brute = make_brute_force_accel(scene);
        const BvhAccel bvh(scene);
        // Through each object's box near its centre from outside it, along the six axes (off the
        // centre itself, where an icosphere has a vertex that several triangles share).
        std::vector<collision::Ray> rays;
        for (const Object& o : scene.objects) {
            const collision::Bounds3 box = object_world_bounds(o, scene.meshes);
            const glm::vec3 centre = box.lo + glm::vec3(0.45f, 0.55f, 0.4f) * (box.hi - box.lo);
            for (int k = 0; k < 6; ++k) {
                glm::vec3 d(-0.0f);
                d[k / 2] = k % 2 ? 1.0f : -1.0f;
                rays.push_back(collision::Ray{centre - d * (box.hi[k / 2] - box.lo[k / 2]), d});
            }
        }
        compare(scene, *brute, bvh, rays, tally);
    }
    CHECK(tally.hits > tally.rays / 2);  // the rays do exercise hits
}

TEST_CASE("accel: Embree finds the same objects and triangles as the native BVH, t within the bound", "[accel][embree]") {
    Tally tally;
    double worst_ratio = 0.0;
    for (bool robust : {false, true}) {
        for (std::uint32_t seed : {1u, 2u, 3u}) {
            const Scene scene = seed == 3 ? test::mesh_scene(seed) : test::mixed_scene(seed, seed == 2 ? 3.0f : 10.0f);
            const BvhAccel bvh(scene);
            EmbreeOptions options;
            options.robust = robust;
            const auto embree = make_embree_accel(scene, options);
            for (const collision::Ray& ray : random_rays(scene, 3000, seed + 10)) {
                SurfaceHit a, b;
                const bool ha = bvh.intersect(ray, a);
                const bool hb = embree->intersect(ray, b);
                ++tally.rays;
                REQUIRE(ha == hb);
                REQUIRE(embree->occluded(ray) == hb);
                if (!ha) continue;
                ++tally.hits;
                REQUIRE(a.object == b.object);
                REQUIRE(a.primitive == b.primitive);
                if (!std::holds_alternative<MeshInstance>(scene.objects[a.object].shape)) {
                    CHECK(a.t == b.t);  // both ran geometry/intersect_object on the same ray
                    continue;
                }
                const TReference ref = plane_t(scene, a, ray);
                INFO("t_ref " << ref.t << " bound " << ref.bound << " native " << a.t << " embree " << b.t);
                CHECK(std::abs(a.t - ref.t) <= ref.bound);
                CHECK(std::abs(b.t - ref.t) <= ref.bound);
                worst_ratio = std::max({worst_ratio, std::abs(a.t - ref.t) / ref.bound, std::abs(b.t - ref.t) / ref.bound});
            }
        }
    }
    CHECK(tally.hits > tally.rays / 4);
    CHECK(worst_ratio > 0.0);  // the bound is checked against real differences, not all-zero ones
}

// The top level's slot spheres (untransformed spheres, raytracer/accel/wide_traversal.hpp): the
// nearest hit decided by intersect_sphere_candidate and finished once, and occluded() testing a
// node's sphere children together (all at once in AVX2, one by one on the scalar path). On a
// field of many small spheres, touching and overlapping ones, a huge ground sphere and a few
// other objects between them: the AVX2 and scalar paths give the same hits bit for bit, and
// both agree with the brute-force reference (every object, in order) on hit, t and object.
#include <catch2/catch.hpp>

#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "accel_test_scenes.hpp"
#include "raytracer/accel/brute_force_accel.hpp"
#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/accel/simd_path.hpp"

using namespace sweeptrace;

namespace {

Scene sphere_field(std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-0.3f, 0.3f), radius(0.05f, 0.45f);
    Scene scene;
    scene.materials.push_back(Material{});
    scene.meshes.push_back(test::icosphere(1));
    scene.objects.push_back(test::object(collision::Sphere{{0.0f, -1000.0f, 0.0f}, 1000.0f}, {}, "ground"));
    for (int x = -8; x <= 8; ++x)
        for (int z = -8; z <= 8; ++z) {
            const float r = radius(rng);
            const glm::vec3 c(float(x) + jitter(rng), r, float(z) + jitter(rng));
            scene.objects.push_back(test::object(collision::Sphere{c, r}, {}, "sphere"));
            if ((x + z) % 9 == 0)  // a touching neighbour: tangent spheres
                scene.objects.push_back(test::object(collision::Sphere{c + glm::vec3(2.0f * r, 0.0f, 0.0f), r}, {}, "touching"));
        }
    scene.objects.push_back(test::object(collision::Sphere{{0.0f, 1.0f, 0.0f}, 1.0f}, {}, "big"));
    scene.objects.push_back(test::object(collision::Sphere{{0.3f, 1.2f, 0.1f}, 0.7f}, {}, "overlapping"));
    scene.objects.push_back(test::object(collision::Sphere{{4.0f, 1.0f, 0.0f}, 1.0f}, test::random_transform(rng, {4, 1, 0}, 1.0f), "transformed"));
    scene.objects.push_back(test::object(MeshInstance{0}, test::make_transform({-4, 1, 0}, {0, 1, 0}, 30.0f, glm::vec3(1.0f)), "mesh"));
    scene.objects.push_back(test::object(collision::Aabb{{0.0f, 0.5f, 4.0f}, glm::vec3(1.0f)}, {}, "box"));
    return scene;
}

template <class T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("wide bvh: slot spheres give the same hits on the AVX2 and scalar paths and as brute force", "[accel][wide]") {
    const Scene scene = sphere_field(5);
    const BvhAccel scalar(scene, SimdPath::Scalar);
    const BvhAccel simd(scene, cpu_has_avx2() ? SimdPath::Avx2 : SimdPath::Scalar);
    const std::unique_ptr<Accel> brute = make_brute_force_accel(scene);
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(-9.0f, 9.0f), h(0.05f, 6.0f), unit(0.0f, 1.0f);
    int hits = 0, blocked = 0;
    for (int i = 0; i < 6000; ++i) {
        const glm::vec3 origin(u(rng), h(rng), u(rng));
        const glm::vec3 target(u(rng), i % 2 ? 0.0f : h(rng), u(rng));
        collision::Ray ray{origin, target - origin};
        if (i % 3 == 0) ray.tmax = unit(rng);  // a segment: occluded() as shadow rays use it
        if (i % 7 == 0) ray.tmin = -unit(rng);
        SurfaceHit a, b, c;
        const bool ha = scalar.intersect(ray, a), hb = simd.intersect(ray, b), hc = brute->intersect(ray, c);
        REQUIRE(ha == hb);
        REQUIRE(ha == hc);
        const bool oa = scalar.occluded(ray);
        REQUIRE(oa == simd.occluded(ray));
        REQUIRE(oa == brute->occluded(ray));
        REQUIRE(oa == ha);
        blocked += oa;
        if (!ha) continue;
        ++hits;
        REQUIRE(a.object == b.object);
        REQUIRE(same_bits(a.t, b.t));
        REQUIRE(same_bits(a.point, b.point));
        REQUIRE(same_bits(a.point_error, b.point_error));
        REQUIRE(same_bits(a.normal, b.normal));
        REQUIRE(same_bits(a.t, c.t));  // the nearest t is one value whatever the visiting order
    }
    CHECK(hits > 3000);
    CHECK(blocked < 5900);
}

// A hit's world point_error must hold the exact surface: the exact surface (the object-space
// shape mapped by the float to_world, in double) must cross the box hit.point +- point_error.
// Near the hit the surface is its tangent plane (curvature terms are far below float rounding
// at these distances), and a plane crosses the box iff |n . (p - s)| <= dot(|n|, error) for a
// surface point s. That is also exactly what spawn_ray's offset relies on.
#include <catch2/catch.hpp>

#include <random>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/matrix.hpp>

#include "accel_test_scenes.hpp"
#include "raytracer/geometry/intersect_object.hpp"

using namespace sweeptrace;

namespace {

// Distance of the hit point from the exact surface along the surface normal, in double.
double surface_distance(const Scene& scene, const SurfaceHit& hit, glm::dvec3& normal) {
    const Object& object = scene.objects[hit.object];
    const glm::dmat4 m(object.transform.to_world);
    const glm::dmat4 inv = glm::inverse(m);
    const glm::dvec3 p(hit.point);
    if (const auto* s = std::get_if<collision::Sphere>(&object.shape)) {
        const glm::dvec3 q = glm::dvec3(inv * glm::dvec4(p, 1.0));
        const glm::dvec3 radial = glm::normalize(q - glm::dvec3(s->center));
        const glm::dvec3 surface = glm::dvec3(s->center) + double(s->radius) * radial;
        const glm::dvec3 surface_world = glm::dvec3(m * glm::dvec4(surface, 1.0));
        normal = glm::normalize(glm::transpose(glm::dmat3(inv)) * radial);
        return glm::dot(normal, p - surface_world);
    }
    const Mesh& mesh = scene.meshes[std::get<MeshInstance>(object.shape).mesh];
    const collision::Triangle t = mesh.triangles.triangle(hit.primitive);
    const glm::dvec3 a = glm::dvec3(m * glm::dvec4(glm::dvec3(t.a), 1.0));
    const glm::dvec3 b = glm::dvec3(m * glm::dvec4(glm::dvec3(t.b), 1.0));
    const glm::dvec3 c = glm::dvec3(m * glm::dvec4(glm::dvec3(t.c), 1.0));
    normal = glm::normalize(glm::cross(b - a, c - a));
    return glm::dot(normal, p - a);
}

// One sphere and one icosphere mesh, transformed (rotation, non-uniform scale ~ `scale`) and
// placed `offset` away from the origin.
Scene scaled_scene(float scale, float offset, std::mt19937& rng) {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.meshes.push_back(test::icosphere(2));
    scene.objects.push_back(test::object(collision::Sphere{glm::vec3(0.0f), 1.0f},
                                         test::random_transform(rng, glm::vec3(offset, 0.5f * offset, 0.0f), scale)));
    scene.objects.push_back(test::object(MeshInstance{0},
                                         test::random_transform(rng, glm::vec3(-offset, 0.0f, 0.3f * offset), scale)));
    scene.objects.push_back(test::object(collision::Sphere{glm::vec3(offset, 0.0f, -offset), scale}));
    return scene;
}

}  // namespace

TEST_CASE("geometry: the world hit point's error bound holds the exact transformed surface", "[geometry]") {
    std::mt19937 rng(21);
    int hits = 0;
    double worst = 0.0;
    for (float scale : {1e-4f, 1e-2f, 1.0f, 1e2f, 1e5f}) {
        for (float offset_factor : {0.0f, 10.0f, 1e3f}) {
            const float offset = scale * offset_factor;
            const Scene scene = scaled_scene(scale, offset, rng);
            for (std::uint32_t obj = 0; obj < scene.objects.size(); ++obj) {
                const glm::vec3 centre(scene.objects[obj].transform.to_world[3]);
                const glm::vec3 target = obj == 2 ? glm::vec3(offset, 0.0f, -offset) : centre;
                for (int i = 0; i < 300; ++i) {
                    const glm::vec3 dir = test::random_direction(rng);
                    // From outside toward the object, and from its centre outward (inside hits).
                    const bool from_inside = i % 3 == 0;
                    const glm::vec3 origin = from_inside ? target : target - 4.0f * scale * dir;
                    std::uniform_real_distribution<float> jitter(-0.5f * scale, 0.5f * scale);
                    const glm::vec3 aim = from_inside ? dir : dir + glm::vec3(jitter(rng), jitter(rng), jitter(rng)) / (4.0f * scale);
                    SurfaceHit hit;
                    if (!intersect_object(scene.objects, scene.meshes, obj, collision::Ray{origin, aim}, hit)) continue;
                    ++hits;
                    glm::dvec3 n;
                    const double distance = surface_distance(scene, hit, n);
                    const double allowed = glm::dot(glm::abs(n), glm::dvec3(hit.point_error));
                    INFO("scale " << scale << " offset " << offset << " object " << obj << " distance " << distance
                                  << " allowed " << allowed);
                    REQUIRE(std::abs(distance) <= allowed);
                    worst = std::max(worst, std::abs(distance) / allowed);
                    // The normal is unit and the shading normal in its hemisphere.
                    CHECK(std::abs(glm::length(hit.normal) - 1.0f) < 1e-6f);
                    CHECK(glm::dot(hit.normal, hit.shading_normal) > 0.0f);
                    CHECK(glm::dot(glm::dvec3(hit.normal), n) > 0.99);  // outward, agreeing with the exact one
                }
            }
        }
    }
    CHECK(hits > 3000);
    CHECK(worst > 0.0);  // the bound was tested against non-zero errors
}

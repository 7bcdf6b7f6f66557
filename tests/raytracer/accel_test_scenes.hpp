#pragma once
// Scenes built in code for the geometry and acceleration tests: seeded, small, covering every
// kind of object the structures handle (analytic shapes, transformed analytic shapes, meshes
// instanced several times under different transforms).
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "raytracer/scene/scene.hpp"

namespace sweeptrace::test {

// Unit icosphere (radius 1, centred at 0), subdivided `levels` times: closed, convex,
// counter-clockwise seen from outside, 20 * 4^levels triangles. Vertex normals = positions.
inline Mesh icosphere(int levels) {
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    std::vector<glm::uvec3> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (glm::vec3& p : v) p = glm::normalize(p);
    for (int l = 0; l < levels; ++l) {
        std::vector<glm::uvec3> next;
        std::vector<std::pair<std::uint64_t, std::uint32_t>> cache;
        auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            for (const auto& [k, i] : cache)
                if (k == key) return i;
            v.push_back(glm::normalize(v[a] + v[b]));
            cache.emplace_back(key, static_cast<std::uint32_t>(v.size() - 1));
            return static_cast<std::uint32_t>(v.size() - 1);
        };
        for (const glm::uvec3& t : f) {
            const std::uint32_t ab = mid(t.x, t.y), bc = mid(t.y, t.z), ca = mid(t.z, t.x);
            next.insert(next.end(), {{t.x, ab, ca}, {t.y, bc, ab}, {t.z, ca, bc}, {ab, bc, ca}});
        }
        f = std::move(next);
    }
    Mesh m;
    m.triangles.vertices = v;
    m.triangles.indices = f;
    m.vertex_normals = v;
    m.source = "icosphere";
    return m;
}

inline Transform make_transform(const glm::vec3& translate, const glm::vec3& axis, float degrees,
                                const glm::vec3& scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
    m = glm::rotate(m, glm::radians(degrees), glm::normalize(axis));
    m = glm::scale(m, scale);
    return Transform::from_matrix(m);
}

inline Object object(Shape shape, Transform xf = {}, std::string name = "") {
    Object o;
    o.shape = std::move(shape);
    o.transform = xf;
    o.name = std::move(name);
    return o;
}

// A random rotation axis, angle and mildly non-uniform scale around `scale`.
inline Transform random_transform(std::mt19937& rng, const glm::vec3& translate, float scale) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), s(0.6f, 1.6f), angle(0.0f, 360.0f);
    glm::vec3 axis(u(rng), u(rng), u(rng));
    if (glm::dot(axis, axis) < 1e-3f) axis = glm::vec3(0, 1, 0);
    return make_transform(translate, axis, angle(rng), scale * glm::vec3(s(rng), s(rng), s(rng)));
}

// Every analytic shape, plain and transformed, plus a mesh instanced three times, spread over
// a box of half size `extent`.
inline Scene mixed_scene(std::uint32_t seed, float extent = 10.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-extent, extent), size(0.3f, 1.5f);
    Scene scene;
    scene.materials.push_back(Material{});
    scene.meshes.push_back(icosphere(2));
    auto p = [&] { return glm::vec3(pos(rng), pos(rng), pos(rng)); };
    for (int i = 0; i < 6; ++i) {
        // Each shape at its own random place (shapes sharing a centre would tie on shared faces).
        const bool transformed = i % 2 == 1;
        auto xf = [&] { return transformed ? random_transform(rng, p(), 1.0f) : Transform{}; };
        auto c = [&] { return transformed ? glm::vec3(0.0f) : p(); };
        const float r = size(rng);
        glm::vec3 k;
        scene.objects.push_back(object(collision::Sphere{c(), r}, xf(), "sphere"));
        scene.objects.push_back(object(collision::Aabb{c(), glm::vec3(r, 2 * r, 0.7f * r)}, xf(), "box"));
        scene.objects.push_back(object(collision::Cylinder{c(), r, 2 * r}, xf(), "cylinder"));
        scene.objects.push_back(object(collision::Capsule{c(), 0.5f * r, r}, xf(), "capsule"));
        scene.objects.push_back(object(collision::Ellipsoid{c(), glm::vec3(r, 0.5f * r, 0.8f * r)}, xf(), "ellipsoid"));
        scene.objects.push_back(object(collision::Disk{c(), glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f)), r}, xf(), "disk"));
        scene.objects.push_back(object(collision::Quad{c(), glm::vec3(r, 0, 0.2f), glm::vec3(0, 0.4f, r)}, xf(), "quad"));
        k = c();
        scene.objects.push_back(object(collision::Triangle{k, k + glm::vec3(r, 0, 0), k + glm::vec3(0, r, 0.3f)}, xf(), "triangle"));
    }
    for (int i = 0; i < 3; ++i)
        scene.objects.push_back(object(MeshInstance{0}, random_transform(rng, p(), 2.0f), "icosphere"));
    scene.objects.push_back(object(MeshInstance{0}, Transform{}, "icosphere at the origin"));
    return scene;
}

// Many meshes' worth of triangles: a grid of instanced icospheres plus one big untransformed
// one, for the mesh-heavy path.
inline Scene mesh_scene(std::uint32_t seed) {
    std::mt19937 rng(seed);
    Scene scene;
    scene.materials.push_back(Material{});
    scene.meshes.push_back(icosphere(3));
    scene.meshes.push_back(icosphere(1));
    for (int x = -2; x <= 2; ++x)
        for (int z = -2; z <= 2; ++z)
            scene.objects.push_back(object(MeshInstance{static_cast<std::uint32_t>((x + z) & 1)},
                                           random_transform(rng, glm::vec3(4.0f * x, 0.0f, 4.0f * z), 1.2f)));
    return scene;
}

// Uniform random direction (not normalised to exactly 1; the structures do not need it).
inline glm::vec3 random_direction(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    for (;;) {
        const glm::vec3 d(n(rng), n(rng), n(rng));
        const float l = glm::length(d);
        if (l > 1e-3f) return d / l;
    }
}

}  // namespace sweeptrace::test

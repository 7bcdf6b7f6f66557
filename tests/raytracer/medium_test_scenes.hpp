#pragma once
// The medium scenes two media test files render (test_render_media.cpp, test_media_vdb.cpp): a
// ball of any medium over a floor under a lamp, and the z-test of two renders of it block by block.
#include <cmath>

#include <glm/mat4x4.hpp>

#include "convergence_harness.hpp"
#include "render_test_scenes.hpp"
#include "render_test_stats.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace::test {

// A sphere of radius 1 bounding `m` (an interface surface: no scattering there), a diffuse floor
// and a quad light above, seen from outside in vacuum.
inline Scene medium_ball_scene(const Medium& m) {
    Scene scene = sweeptrace::testing::empty_scene(24, 24);
    scene.camera.position = glm::vec3(0.0f, 0.5f, 4.0f);
    scene.camera.look_at = glm::vec3(0.0f, 0.0f, 0.0f);
    scene.camera.vfov_degrees = 45.0f;
    scene.media.push_back(m);
    Material boundary;
    boundary.type = Material::Type::Interface;
    sweeptrace::testing::add_object(scene, collision::Sphere{glm::vec3(0.0f), 1.0f}, add_material(scene, boundary),
                                    glm::mat4(1.0f), "ball");
    scene.objects.back().media.inside = 0;
    Material floor = sweeptrace::testing::diffuse(0.6f);
    sweeptrace::testing::add_object(
        scene, collision::Quad{glm::vec3(-4.0f, -1.0f, 4.0f), glm::vec3(8.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, -8.0f)},
        add_material(scene, floor), glm::mat4(1.0f), "floor");
    Material lamp;
    lamp.type = Material::Type::Emissive;
    lamp.albedo = glm::vec3(0.0f);
    lamp.emission = glm::vec3(6.0f, 5.0f, 4.0f);
    sweeptrace::testing::add_object(
        scene, collision::Quad{glm::vec3(-0.5f, 2.5f, -0.5f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)},
        add_material(scene, lamp), glm::mat4(1.0f), "lamp");
    return scene;
}

// Blocks of 4 x 4 pixels of two independent renders: how many differ beyond their joint noise.
inline int blocks_apart(const RenderResult& a, const RenderResult& b) {
    const int blocks = (a.image.width / 4) * (a.image.height / 4) * 3;
    int apart = 0;
    for (int by = 0; by + 4 <= a.image.height; by += 4)
        for (int bx = 0; bx + 4 <= a.image.width; bx += 4)
            for (int c = 0; c < 3; ++c) {
                double ma = 0.0, mb = 0.0, va = 0.0, vb = 0.0;
                for (int y = by; y < by + 4; ++y)
                    for (int x = bx; x < bx + 4; ++x) {
                        ma += a.image.at(x, y)[c] / 16.0;
                        mb += b.image.at(x, y)[c] / 16.0;
                        va += a.variance.at(x, y)[c] / 256.0;
                        vb += b.variance.at(x, y)[c] / 256.0;
                    }
                apart += std::abs(ma - mb) > z_bound(blocks) * std::sqrt(va + vb) + 1e-5 * (ma + mb);
            }
    return apart;
}

}  // namespace sweeptrace::test

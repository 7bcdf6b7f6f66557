#pragma once
// The white-furnace scene the material energy tests share: a unit sphere of one material alone
// under a constant environment, seen head-on, and the 4 x 4-pixel blocks that lie wholly on it.
// Every block's mean may not exceed the environment beyond its noise (no energy gain).
#include <cmath>
#include <vector>

#include "convergence_harness.hpp"
#include "raytracer/geometry/surface_hit.hpp"

namespace sweeptrace::testing {

// A hit on a flat surface whose normal is +z, for BSDF-level tests.
inline SurfaceHit flat_z_hit() {
    SurfaceHit h;
    h.normal = {0.0f, 0.0f, 1.0f};
    h.shading_normal = h.normal;
    return h;
}

inline constexpr int kFurnaceSize = 32;

inline Scene sphere_furnace(const Material& m, const glm::vec3& environment) {
    Scene scene = empty_scene(kFurnaceSize, kFurnaceSize);
    scene.background.color = environment;
    scene.camera.position = {0.0f, 0.0f, 3.2f};
    scene.camera.look_at = glm::vec3(0.0f);
    scene.camera.vfov_degrees = 40.0f;  // the sphere covers the middle of the frame
    add_object(scene, collision::Sphere{glm::vec3(0.0f), 1.0f}, add_material(scene, m), glm::mat4(1.0f), "sphere");
    return scene;
}

struct BlockMean {
    double mean = 0.0, standard_error = 0.0;
};

// The 9 blocks of the central 12 x 12 pixels (all on the sphere), of one channel (green unless told).
inline std::vector<BlockMean> sphere_blocks(const RenderResult& r, int channel = 1) {
    std::vector<BlockMean> blocks;
    for (int by = 10; by < 22; by += 4)
        for (int bx = 10; bx < 22; bx += 4) {
            double sum = 0.0, var = 0.0;
            for (int y = by; y < by + 4; ++y)
                for (int x = bx; x < bx + 4; ++x) {
                    sum += r.image.at(x, y)[channel];
                    var += r.variance.at(x, y)[channel];
                }
            blocks.push_back({sum / 16.0, std::sqrt(var) / 16.0});
        }
    return blocks;
}

}  // namespace sweeptrace::testing

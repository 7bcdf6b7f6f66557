#pragma once
// The analytic image of the plane z = 0 under a uniform sky, seen by the tests' pinhole camera at
// (0, 0, 3) looking at the origin with a 50-degree field of view on a square film: each pixel the
// mean of sub x sub sub-pixel values, and the mask of the pixels whose sub-samples all fall in
// one region (the others straddle an edge). And the check that a render of such a scene reads
// the truth at every masked pixel with both accels.
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include <catch2/catch.hpp>

#include "convergence_harness.hpp"

namespace sweeptrace::testing {

struct PlaneTruth {
    Image image;
    std::vector<std::uint8_t> mask;
};

// `region(x, y)` names the region of the plane's world point (x, y); `value(region)` its radiance.
inline PlaneTruth plane_truth(int size, int sub, const std::function<int(double, double)>& region,
                              const std::function<glm::vec3(int)>& value) {
    const double half = std::tan(glm::radians(25.0));
    PlaneTruth t{Image(size, size), std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size, 1)};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            glm::dvec3 sum(0.0);
            int first = -1;
            for (int j = 0; j < sub; ++j)
                for (int i = 0; i < sub; ++i) {
                    const double fx = x + (i + 0.5) / sub, fy = y + (j + 0.5) / sub;
                    const int cell = region((2 * fx / size - 1) * half * 3, (1 - 2 * fy / size) * half * 3);
                    if (first < 0) first = cell;
                    if (cell != first) t.mask[static_cast<std::size_t>(y) * size + x] = 0;
                    sum += glm::dvec3(value(cell));
                }
            t.image.at(x, y) = glm::vec3(sum / double(sub * sub));
        }
    return t;
}

// The scene plane_truth's camera sees: a square film of `size` pixels, the camera at (0, 0, 3)
// looking at the origin with a 50-degree field of view, nothing in it yet.
inline Scene plane_test_scene(int size) {
    Scene scene = empty_scene(size, size);
    scene.camera.position = {0.0f, 0.0f, 3.0f};
    scene.camera.vfov_degrees = 50.0f;
    return scene;
}

// The checker the plane tests texture a unit square with (3 x 3 squares over it, uv = its object
// x, y), and the region of world point (wx, wy) once the square is moved to [-1, 1]^2 (scale 2,
// translate -1): 0 or 1, the checker's colours a or b; 2, off the square.
inline Texture plane_checker() {
    Texture checker;
    checker.a = glm::vec3(0.2f);
    checker.b = glm::vec3(0.7f, 0.5f, 0.3f);
    checker.scale = 3.0f;
    return checker;
}
inline int checker_square_region(double wx, double wy) {
    const double u = (wx + 1) / 2, v = (wy + 1) / 2;
    const bool on = u > 0 && u < 1 && v > 0 && v < 1;
    return on ? int(std::floor(3 * u) + std::floor(3 * v)) % 2 : 2;
}
inline glm::mat4 checker_square_placement() {
    return glm::translate(glm::mat4(1.0f), {-1.0f, -1.0f, 0.0f}) * glm::scale(glm::mat4(1.0f), glm::vec3(2.0f));
}

// Deterministic: every sample of a masked pixel reads exactly albedo x L (a diffuse surface facing
// only the sky; the cosine sample's weight is the albedo); 1e-6 covers its roundings.
inline void check_plane_render(const Scene& scene, const PlaneTruth& truth) {
    for (AccelKind accel : {AccelKind::Bvh, AccelKind::Embree}) {
        const RenderResult r = render_with(scene, accel, 8, 3, 4);
        const BlockTestResult t = test_against_truth(truth.image, r, 2, 1e-6, &truth.mask);
        INFO((accel == AccelKind::Bvh ? "bvh: " : "embree: ") << t.summary());
        CHECK(t.pass());
        CHECK(t.blocks_tested > 150);
    }
}

}  // namespace sweeptrace::testing

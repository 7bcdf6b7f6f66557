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

#pragma once
// The identity of a made-up render for the farm tests' parts (image/partial_image.hpp): fixed
// scene hash, accelerator and version, the fields a test varies as arguments.
#include <cstdint>
#include <string>

#include "raytracer/image/partial_image.hpp"

namespace sweeptrace::test {

inline RenderIdentity farm_test_identity(int width, int height, std::uint64_t seed, int max_depth,
                                         const std::string& integrator, int spp, const std::string& adaptive = "off",
                                         const std::string& sampler = "sobol") {
    RenderIdentity id;
    id.scene_hash = "0123456789abcdef";
    id.width = width;
    id.height = height;
    id.seed = seed;
    id.max_depth = max_depth;
    id.accel = "bvh";
    id.integrator = integrator;
    id.sampler = sampler;
    id.adaptive = adaptive;
    id.version = "test";
    id.spp = spp;
    return id;
}

}  // namespace sweeptrace::test

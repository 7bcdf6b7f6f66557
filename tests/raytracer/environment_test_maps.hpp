#pragma once
// The environment light's tests share these: a map with every kind of texel weight, the
// Background around a map, a small scene of two spheres on a floor under a background, and the
// z-test of two independent renders of it.
#include <memory>
#include <utility>

#include "convergence_harness.hpp"
#include "raytracer/scene/scene.hpp"

namespace sweeptrace::testing {

// A W x H map with a smooth gradient, a dark band and one bright texel: every kind of weight.
inline std::shared_ptr<const Image> environment_test_map(int w, int h) {
    auto img = std::make_shared<Image>(w, h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) img->at(i, j) = glm::vec3(0.2f + 0.1f * i / w, 0.5f * j / h, j == h / 2 ? 0.0f : 0.3f);
    for (int i = 0; i < w; ++i) img->at(i, h / 3) = glm::vec3(0.0f);  // a black row: never sampled
    img->at(w / 4, h / 4) = glm::vec3(40.0f, 30.0f, 20.0f);
    return img;
}

inline Background env_background(std::shared_ptr<const Image> img, float rotate, float scale,
                                 Background::EnvironmentMapping mapping = Background::EnvironmentMapping::Equirect,
                                 bool mirror = false) {
    Background bg;
    bg.kind = Background::Kind::Environment;
    bg.environment = std::move(img);
    bg.mapping = mapping;
    bg.rotate_degrees = rotate;
    bg.mirror = mirror;
    bg.scale = scale;
    return bg;
}

inline Scene spheres_under(const Background& bg, int size) {
    Scene scene = empty_scene(size, size);
    scene.camera.position = {0.0f, 1.0f, 4.0f};
    scene.camera.look_at = {0.0f, 0.3f, 0.0f};
    scene.background = bg;
    add_object(scene, collision::Sphere{{-0.6f, 0.5f, 0.0f}, 0.5f}, add_material(scene, diffuse(0.7f)), glm::mat4(1.0f), "a");
    Material metal;
    metal.type = Material::Type::Metal;
    metal.albedo = glm::vec3(0.9f);
    metal.roughness = 0.3f;
    add_object(scene, collision::Sphere{{0.6f, 0.5f, 0.0f}, 0.5f}, add_material(scene, metal), glm::mat4(1.0f), "b");
    add_object(scene, collision::Quad{{-3.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 6.0f}, {6.0f, 0.0f, 0.0f}},
               add_material(scene, diffuse(0.5f)), glm::mat4(1.0f), "floor");
    return scene;
}

// Two independent renders agree within their summed variances (block z-test).
inline BlockTestResult renders_agree(const RenderResult& a, const RenderResult& b) {
    Image variance(a.image.width, a.image.height);
    for (std::size_t i = 0; i < variance.pixels.size(); ++i) variance.pixels[i] = a.variance.pixels[i] + b.variance.pixels[i];
    BlockTestOptions options;
    options.block = 4;
    options.golden_is_8bit = false;
    return block_test(a.image, b.image, variance, options);
}

}  // namespace sweeptrace::testing

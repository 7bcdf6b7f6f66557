#pragma once
// Small scenes with a known answer, built in code, and the z-test of a render against the
// answer (block_test with an analytic reference: no 8-bit rounding, variance from the render).
#include <cmath>
#include <cstring>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "raytracer/accel/accel.hpp"
#include "raytracer/image/diff.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/scene.hpp"
#include "render_test_scenes.hpp"

namespace sweeptrace::testing {

inline Scene empty_scene(int width, int height) {
    Scene scene;
    scene.film.width = width;
    scene.film.height = height;
    return scene;
}

// One home (render_test_scenes.hpp): a test file that uses both helper namespaces, or a unity
// batch that joins two such files, must find one add_material, not two.
using sweeptrace::test::add_material;

inline Material diffuse(float rho) {
    Material m;
    m.type = Material::Type::Diffuse;
    m.albedo = glm::vec3(rho);
    return m;
}

inline void add_object(Scene& scene, Shape shape, std::uint32_t material, const glm::mat4& to_world, std::string name) {
    Object o;
    o.shape = shape;
    o.material = material;
    o.transform = Transform::from_matrix(to_world);
    o.name = std::move(name);
    scene.objects.push_back(std::move(o));
}

// render/camera.hpp's pinhole model in double, for analytic truths: the direction (not
// normalised; its component along the view axis is 1) through film position (fx, fy), in
// pixels from the top-left corner of a width x height image.
struct PinholeRays {
    glm::dvec3 eye, forward, right, up;
    double half_height, half_width;  // in this order: half_width is made from half_height
    int width, height;
    PinholeRays(const Camera& c, int w, int h)
        : eye(c.position), forward(glm::normalize(glm::dvec3(c.look_at) - eye)),
          right(glm::normalize(glm::cross(forward, glm::dvec3(c.up)))), up(glm::cross(right, forward)),
          half_height(std::tan(0.5 * glm::radians(static_cast<double>(c.vfov_degrees)))),
          half_width(half_height * w / h), width(w), height(h) {}
    glm::dvec3 direction(double fx, double fy) const {
        return forward + (2.0 * fx / width - 1.0) * half_width * right + (1.0 - 2.0 * fy / height) * half_height * up;
    }
};

// A convex closed mesh: the icosahedron subdivided `levels` times, vertices pushed onto the unit
// sphere, counter-clockwise seen from outside (outward normals).
collision::TriangleMesh icosphere(int levels);

inline RenderResult render_with(const Scene& scene, AccelKind kind, int spp, int max_depth, std::uint64_t seed,
                                Sampling sampling = Sampling::NeeMis) {
    const auto accel = make_accel(kind, scene);
    RenderOptions options;
    options.spp = spp;
    options.max_depth = max_depth;
    options.seed = seed;
    options.sampling = sampling;
    return render(scene, *accel, options);
}

// block_test against an analytic image: a family-wise false alarm of 1e-4 over every block and
// channel, `relative_tolerance` the float rounding of the renderer's estimate (stated per test).
inline BlockTestResult test_against_truth(const Image& truth, const RenderResult& r, int block,
                                          double relative_tolerance, const std::vector<std::uint8_t>* mask) {
    BlockTestOptions options;
    options.block = block;
    options.golden_is_8bit = false;
    options.relative_tolerance = relative_tolerance;
    options.mask = mask;
    return block_test(truth, r.image, r.variance, options);
}

// The mean over pixels of a render's per-pixel variance (luminance): its noise in one number.
inline double mean_pixel_variance(const Image& variance) {
    double sum = 0.0;
    for (const glm::vec3& v : variance.pixels) sum += luminance(v);
    return sum / static_cast<double>(variance.pixels.size());
}

// Same size and the same pixels bit for bit (NaNs and signed zeros included).
inline bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

// A short render (3 spp, depth 4, seed 9) on 1 and on 3 threads, for the determinism checks.
struct OneAndThreeThreads {
    RenderResult one, three;
};
inline OneAndThreeThreads render_on_1_and_3_threads(const Scene& scene, const Accel& accel) {
    RenderOptions o;
    o.spp = 3;
    o.max_depth = 4;
    o.seed = 9;
    o.threads = 1;
    OneAndThreeThreads r{render(scene, accel, o), {}};
    o.threads = 3;
    r.three = render(scene, accel, o);
    return r;
}

}  // namespace sweeptrace::testing

// White furnace: a diffuse convex object of albedo rho under a constant environment L reads
// rho * L at every pixel it fully covers. A convex surface (flat ones included) never sees
// itself, so every bounced ray escapes to the environment after exactly one scattering: any
// deviation is an intersector, transform, offset (acne: a second scattering) or sampling bug.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "convergence_harness.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

const glm::vec3 environment(0.9f, 0.7f, 0.5f);
const glm::vec3 albedo(0.7f, 0.5f, 0.3f);
constexpr int size = 48, spp = 16, block = 4;

Scene furnace(const Shape& shape, const glm::mat4& to_world, const glm::vec3& rho, const std::vector<Mesh>& meshes) {
    Scene scene = empty_scene(size, size);
    scene.meshes = meshes;
    scene.camera.position = {0.0f, 0.0f, 4.0f};
    scene.camera.look_at = glm::vec3(0.0f);
    scene.camera.vfov_degrees = 40.0f;
    scene.background.kind = Background::Kind::Constant;
    scene.background.color = environment;
    Material m = diffuse(0.0f);
    m.albedo = rho;
    add_object(scene, shape, add_material(scene, m), to_world, "object");
    return scene;
}

// Pixels whose every sample hit the object: exactly 0 when the object is black (albedo 0), then
// eroded by one pixel so that no pixel near the silhouette takes part whatever its samples were.
std::vector<std::uint8_t> covered_pixels(const Image& black_render) {
    const int w = black_render.width, h = black_render.height;
    std::vector<std::uint8_t> mask(black_render.pixels.size(), 0);
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            bool all = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) all = all && black_render.at(x + dx, y + dy) == glm::vec3(0.0f);
            mask[static_cast<std::size_t>(y) * w + x] = all;
        }
    return mask;
}

void check_furnace(const Shape& shape, const glm::mat4& to_world, AccelKind accel,
                   const std::vector<Mesh>& meshes = {}) {
    const RenderResult black = render_with(furnace(shape, to_world, glm::vec3(0.0f), meshes), accel, spp, 8, 3);
    const std::vector<std::uint8_t> mask = covered_pixels(black.image);
    std::size_t covered = 0;
    for (auto m : mask) covered += m;
    REQUIRE(covered >= 100);  // the object fills a good part of the frame

    const RenderResult r = render_with(furnace(shape, to_world, albedo, meshes), accel, spp, 8, 3);
    Image truth(size, size);
    for (auto& p : truth.pixels) p = albedo * environment;
    // Each sample is L times the BSDF weight f cos / pdf: at most 8 float roundings (8 x 2^-24 =
    // 4.8e-7 relative), rounded up to 1e-6; pixel means are summed in double.
    const BlockTestResult t = test_against_truth(truth, r, block, 1e-6, &mask);
    INFO(t.summary() << "; " << covered << " covered pixels");
    CHECK(t.pass());
    CHECK(r.stats.nonfinite_samples == 0);
}

glm::mat4 turned(float degrees, glm::vec3 axis, glm::vec3 scale = glm::vec3(1.0f)) {
    return glm::scale(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::normalize(axis)), scale);
}

}  // namespace

#define FURNACE_TEST(name, shape, transform)                                                                  \
    TEST_CASE("furnace: " name " bvh", "[convergence][furnace]") { check_furnace(shape, transform, AccelKind::Bvh); } \
    TEST_CASE("furnace: " name " embree", "[convergence][furnace]") {                                         \
        check_furnace(shape, transform, AccelKind::Embree);                                                   \
    }

FURNACE_TEST("sphere", (collision::Sphere{glm::vec3(0.0f), 1.0f}), glm::mat4(1.0f))
FURNACE_TEST("scaled sphere", (collision::Sphere{glm::vec3(0.0f), 1.0f}), turned(30.0f, {0, 0, 1}, {1.2f, 0.7f, 1.0f}))
FURNACE_TEST("box", (collision::Aabb{glm::vec3(0.0f), glm::vec3(1.4f, 1.0f, 1.2f)}), turned(30.0f, {1, 1, 0}))
FURNACE_TEST("cylinder", (collision::Cylinder{glm::vec3(0.0f), 0.6f, 1.4f}), turned(40.0f, {1, 0, 1}))
FURNACE_TEST("capsule", (collision::Capsule{glm::vec3(0.0f), 0.5f, 0.8f}), turned(-35.0f, {1, 0.3f, 0.5f}))
FURNACE_TEST("ellipsoid", (collision::Ellipsoid{glm::vec3(0.0f), glm::vec3(1.1f, 0.6f, 0.8f)}), turned(25.0f, {0, 1, 1}))
// Flat convex shapes never see themselves either; seen at an angle, both faces are checked by
// the two accelerators' rays alike.
FURNACE_TEST("disk", (collision::Disk{glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), 1.2f}), turned(35.0f, {1, 0, 0}))
FURNACE_TEST("quad", (collision::Quad{glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(0.0f, 2.0f, 0.0f)}),
             turned(-30.0f, {1, 1, 0}))

namespace {

// An icosphere (convex, 320 triangles) instanced with a rotation and a non-uniform scale.
void check_mesh_furnace(AccelKind accel) {
    Mesh mesh;
    mesh.triangles = icosphere(2);
    mesh.source = "icosphere";
    check_furnace(MeshInstance{0}, turned(20.0f, {1, 2, 0}, {1.2f, 0.9f, 1.0f}), accel, {mesh});
}

}  // namespace

TEST_CASE("furnace: icosphere mesh bvh", "[convergence][furnace]") { check_mesh_furnace(AccelKind::Bvh); }
TEST_CASE("furnace: icosphere mesh embree", "[convergence][furnace]") { check_mesh_furnace(AccelKind::Embree); }

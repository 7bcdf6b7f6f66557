// Textures (render/materials/texture.hpp) and the shapes' uv parameterisations (geometry/shapes/): uv at
// known points of each home that has one, checker and bilinear image lookups with both wrap
// modes, a checker-textured quad under a uniform sky rendering albedo(uv) x L pixel by pixel,
// and textures refused on shapes without uv.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "convergence_harness.hpp"
#include "plane_truth.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/materials/texture.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/obj_loader.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {
bool near(const glm::vec2& a, const glm::vec2& b) { return std::abs(a.x - b.x) < 1e-5f && std::abs(a.y - b.y) < 1e-5f; }
}  // namespace

TEST_CASE("texture: each home's uv at known points", "[render][texture]") {
    const collision::Quad q{{1.0f, 2.0f, 3.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 4.0f}};
    CHECK(near(QuadShape::uv(q, q.corner), {0.0f, 0.0f}));
    CHECK(near(QuadShape::uv(q, q.corner + q.edge_u), {1.0f, 0.0f}));
    CHECK(near(QuadShape::uv(q, q.corner + q.edge_v), {0.0f, 1.0f}));
    CHECK(near(QuadShape::uv(q, q.corner + 0.25f * q.edge_u + 0.75f * q.edge_v), {0.25f, 0.75f}));
    const collision::Triangle t{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 1.0f}, {0.0f, 2.0f, 0.0f}};
    CHECK(near(TriangleShape::uv(t, t.b), {1.0f, 0.0f}));
    CHECK(near(TriangleShape::uv(t, t.c), {0.0f, 1.0f}));
    CHECK(near(TriangleShape::uv(t, (t.a + t.b + t.c) / 3.0f), {1.0f / 3.0f, 1.0f / 3.0f}));
    const collision::Disk d{{0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 2.0f}, 2.0f};
    const Frame f(glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(near(DiskShape::uv(d, d.center + 2.0f * f.s), {0.0f, 1.0f}));
    CHECK(near(DiskShape::uv(d, d.center + 1.0f * f.t), {0.25f, 0.5f}));
    CHECK(near(DiskShape::uv(d, d.center - 1.5f * f.s), {0.5f, 0.75f}));
    const collision::Sphere s{{1.0f, 0.0f, 0.0f}, 2.0f};
    CHECK(near(SphereShape::uv(s, s.center + glm::vec3(2.0f, 0.0f, 0.0f)), {0.0f, 0.5f}));
    CHECK(near(SphereShape::uv(s, s.center + glm::vec3(0.0f, 0.0f, 2.0f)), {0.25f, 0.5f}));
    CHECK(SphereShape::uv(s, s.center + glm::vec3(0.0f, -2.0f, 0.0f)).y == Approx(1.0f));  // the pole; u is arbitrary
    const collision::Ellipsoid e{{0.0f, 1.0f, 0.0f}, {2.0f, 1.0f, 3.0f}};
    CHECK(near(EllipsoidShape::uv(e, e.center + glm::vec3(0.0f, 0.0f, 3.0f)), {0.25f, 0.5f}));
    CHECK(near(EllipsoidShape::uv(e, e.center + glm::vec3(-2.0f, 0.0f, 0.0f)), {0.5f, 0.5f}));
    const collision::Cylinder cy{{0.0f, 1.0f, 0.0f}, 0.5f, 2.0f};
    CHECK(near(CylinderShape::uv(cy, cy.center + glm::vec3(0.0f, 0.5f, 0.5f)), {0.25f, 0.75f}));
    CHECK(near(CylinderShape::uv(cy, cy.center + glm::vec3(0.2f, -1.0f, 0.0f)), {0.0f, 0.0f}));  // bottom cap
    const collision::Capsule ca{{0.0f, 0.0f, 0.0f}, 0.5f, 1.0f};  // y from -1 to 1
    CHECK(near(CapsuleShape::uv(ca, {0.0f, 1.0f, 0.0f}), {0.0f, 1.0f}));
    CHECK(near(CapsuleShape::uv(ca, {-0.5f, 0.5f, 0.0f}), {0.5f, 0.75f}));
    const collision::Aabb b{{1.0f, 0.0f, 0.0f}, {2.0f, 4.0f, 6.0f}};
    CHECK(near(BoxShape::uv(b, b.center + glm::vec3(1.0f, 1.0f, -1.5f)), {0.75f, 0.25f}));   // +x face: (y, z)
    CHECK(near(BoxShape::uv(b, b.center + glm::vec3(0.5f, -2.0f, 3.0f * 0.5f)), {0.75f, 0.75f}));  // -y face: (x, z)
    CHECK(near(BoxShape::uv(b, b.center + glm::vec3(-0.5f, 0.0f, 3.0f)), {0.25f, 0.5f}));  // +z face: (x, y)
}

TEST_CASE("texture: checker parity and bilinear image lookups with repeat and clamp", "[render][texture]") {
    Texture c;
    c.a = glm::vec3(0.1f);
    c.b = glm::vec3(0.9f);
    c.scale = 4.0f;
    CHECK(eval_texture(c, {0.1f, 0.1f}) == c.a);
    CHECK(eval_texture(c, {0.3f, 0.1f}) == c.b);
    CHECK(eval_texture(c, {0.3f, 0.3f}) == c.a);
    CHECK(eval_texture(c, {-0.1f, 0.1f}) == c.b);  // floor, not truncation: the pattern continues
    Texture im;
    im.kind = Texture::Kind::Image;
    auto img = std::make_shared<Image>(2, 2);
    img->at(0, 0) = glm::vec3(0.0f);  // top row
    img->at(1, 0) = glm::vec3(1.0f);
    img->at(0, 1) = glm::vec3(0.5f);  // bottom row: v near 0
    img->at(1, 1) = glm::vec3(0.25f);
    im.image = img;
    CHECK(eval_texture(im, {0.25f, 0.75f}) == glm::vec3(0.0f));   // the top-left texel's centre
    CHECK(eval_texture(im, {0.75f, 0.25f}) == glm::vec3(0.25f));  // the bottom-right texel's centre
    CHECK(eval_texture(im, {0.5f, 0.75f}).x == Approx(0.5f));      // halfway along the top row
    // At u = 0 the lookup is halfway between column 0 and the column before it: column 1 when
    // repeating, column 0 again when clamped.
    CHECK(eval_texture(im, {0.0f, 0.75f}).x == Approx(0.5f));
    im.wrap = Texture::Wrap::Clamp;
    CHECK(eval_texture(im, {0.0f, 0.75f}).x == Approx(0.0f));
}

namespace {

// A checker-textured unit square (object space [0, 1]^2 at z = 0, uv = (x, y)), scaled by 2 and
// moved to [-1, 1]^2, under a uniform sky: every pixel must read albedo(uv) x L. `add_square`
// adds the square (a quad, or an OBJ mesh with vt) with the given material.
void check_checker_square(const std::function<void(Scene&, std::uint32_t, const glm::mat4&)>& add_square) {
    constexpr int size = 32, sub = 8;
    Scene scene = plane_test_scene(size);
    const glm::vec3 L(1.0f, 0.8f, 0.6f);
    scene.background.color = L;
    const Texture checker = plane_checker();
    scene.textures.push_back(checker);
    Material m = diffuse(0.0f);
    m.albedo_texture = 0;
    // The unit quad in object space, scaled by 2 and moved: uv follows the object, not the world.
    add_square(scene, add_material(scene, m), checker_square_placement());
    // Truth: a pixel sees the plane z = 0 at world (x, y); uv = ((x + 1) / 2, (y + 1) / 2) on
    // the quad, the sky elsewhere. A diffuse surface facing only the sky reflects albedo x L.
    const PlaneTruth truth = plane_truth(size, sub, checker_square_region,
                                         [&](int cell) { return cell == 2 ? L : (cell == 0 ? checker.a : checker.b) * L; });
    check_plane_render(scene, truth);
}

}  // namespace

TEST_CASE("texture: a checker quad under a uniform sky renders albedo(uv) x L at every pixel", "[render][texture]") {
    check_checker_square([](Scene& scene, std::uint32_t material, const glm::mat4& xf) {
        add_object(scene, collision::Quad{glm::vec3(0.0f), {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, material, xf, "q");
    });
}

TEST_CASE("texture: an OBJ square with vt renders the same checker through its interpolated uv", "[render][texture]") {
    test::TempDir dir;
    // Two triangles; vt listed in a different order from v, so a mix-up of indices would show.
    const auto file = dir.write("square.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                              "vt 1 1\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                              "f 1/2 2/3 3/1\nf 1/2 3/1 4/4\n");
    const Mesh mesh = load_obj(file);
    REQUIRE(mesh.vertex_uvs.size() == mesh.triangles.vertices.size());
    check_checker_square([&](Scene& scene, std::uint32_t material, const glm::mat4& xf) {
        scene.meshes.push_back(mesh);
        add_object(scene, MeshInstance{0}, material, xf, "square");
    });
}

TEST_CASE("texture: scene keys, and a texture on a shape without uv is refused naming the object", "[scene][texture]") {
    test::TempDir dir;
    const std::string head = R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "film": { "width": 4, "height": 4 },
        "materials": { "c": { "type": "diffuse", "albedo": { "checker": { "a": [0, 0, 0], "b": [1, 1, 1], "scale": 2 } } } },
        "objects": [ )";
    const Scene ok = load_scene(dir.write("ok.json", head + R"({ "type": "sphere", "radius": 1, "material": "c" }] })"));
    REQUIRE(ok.textures.size() == 1);
    CHECK(ok.materials[0].albedo_texture == 0);
    CHECK(ok.textures[0].scale == 2.0f);
    write_image(Image(2, 1), dir.path() / "grey.png");
    const Scene shared = load_scene(dir.write("shared.json", R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
        "film": { "width": 4, "height": 4 }, "objects": [],
        "materials": { "a": { "type": "diffuse", "albedo": { "image": { "file": "grey.png" } } },
                       "b": { "type": "metal", "albedo": { "image": { "file": "./grey.png", "wrap": "clamp" } } } } })"));
    REQUIRE(shared.textures.size() == 2);
    CHECK(shared.textures[0].image == shared.textures[1].image);  // one image, loaded once
    CHECK(shared.textures[1].wrap == Texture::Wrap::Clamp);
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3\n");  // one corner without vt
    try {
        load_scene(dir.write("mesh.json", head + R"({ "type": "box", "size": [1, 1, 1], "material": "c" },
                                                    { "type": "mesh", "file": "tri.obj", "material": "c" }] })"));
        FAIL("a textured mesh loaded");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("objects[1].material: material \"c\" reads a texture, but this mesh has no uv") &&
                                 Catch::Contains("shapes with uv: sphere, box, cylinder, capsule, ellipsoid, disk, quad, triangle"));
    }
}

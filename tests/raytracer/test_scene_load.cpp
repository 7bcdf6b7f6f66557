// The shipped scenes load with the expected contents; OBJ meshes load once and keep their normals.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <utility>
#include <string>
#include <variant>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/obj_loader.hpp"
#include "scene_test_files.hpp"
#include "../shared_meshes.hpp"

using sweeptrace::load_obj;
using sweeptrace::load_scene;
using sweeptrace::Material;
using sweeptrace::Scene;
using sweeptrace::test::TempDir;

namespace {

const std::filesystem::path kScenes = std::filesystem::path(SWEEPTRACE_SOURCE_DIR) / "scenes";

template <class T>
std::size_t count_shapes(const Scene& scene) {
    std::size_t n = 0;
    for (const auto& o : scene.objects) n += std::holds_alternative<T>(o.shape) ? 1 : 0;
    return n;
}

bool uses_material_type(const Scene& scene, Material::Type type) {
    for (const auto& o : scene.objects)
        if (scene.materials[o.material].type == type) return true;
    return false;
}

}  // namespace

TEST_CASE("scenes: every shipped scene loads", "[scene]") {
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
        if (entry.path().extension() != ".json") continue;
        INFO(entry.path());
        const Scene scene = load_scene(entry.path());
        CHECK(scene.film.width > 0);
        CHECK_FALSE(scene.objects.empty());
        ++count;
    }
    CHECK(count >= 2);
}

TEST_CASE("scenes: smallpt is Beason's nine spheres", "[scene]") {
    const Scene scene = load_scene(kScenes / "smallpt.json");
    REQUIRE(scene.objects.size() == 9);
    CHECK(count_shapes<collision::Sphere>(scene) == 9);
    const auto& left = std::get<collision::Sphere>(scene.objects[0].shape);
    CHECK(left.radius == 1e5f);
    CHECK(left.center.x == 100001.0f);  // 1e5 + 1: exact in float
    const auto& light = std::get<collision::Sphere>(scene.objects[8].shape);
    CHECK(scene.materials[scene.objects[8].material].emission == glm::vec3(12.0f));
    CHECK(light.radius == 600.0f);
    CHECK(uses_material_type(scene, Material::Type::Metal));
    CHECK(uses_material_type(scene, Material::Type::Dielectric));
    for (const auto& o : scene.objects) CHECK(o.transform.identity);
    CHECK(scene.camera.position == glm::vec3(50.0f, 52.0f, 295.6f));  // smallpt's own camera
    CHECK(scene.camera.near_clip == 140.0f);
    CHECK(std::tan(scene.camera.vfov_degrees * M_PI / 360.0) == Approx(0.5135 / 2).epsilon(1e-6));
}

TEST_CASE("scenes: the Cornell box has quad walls, a quad light and two rotated boxes", "[scene]") {
    const Scene scene = load_scene(kScenes / "cornell-box.json");
    CHECK(count_shapes<collision::Quad>(scene) == 6);
    CHECK(count_shapes<collision::Aabb>(scene) == 2);
    std::size_t lights = 0;
    for (const auto& o : scene.objects)
        if (scene.materials[o.material].type == Material::Type::Emissive) {
            ++lights;
            // The light faces down into the box.
            const auto& q = std::get<collision::Quad>(o.shape);
            CHECK(glm::cross(q.edge_u, q.edge_v).y < 0.0f);
        }
    CHECK(lights == 1);
    // The tall box: min corner at the origin, rotated 15 degrees about Y, then moved.
    const auto& tall = scene.objects[6];
    REQUIRE(std::holds_alternative<collision::Aabb>(tall.shape));
    CHECK(std::get<collision::Aabb>(tall.shape).size == glm::vec3(165.0f, 330.0f, 165.0f));
    const glm::vec4 corner = tall.transform.to_world * glm::vec4(165.0f, 0.0f, 0.0f, 1.0f);
    const float a = glm::radians(15.0f);
    // Float matrix times float vector of magnitude ~300: a few ulps of 300 (~1e-4) at most.
    CHECK(corner.x == Approx(265.0f + 165.0f * std::cos(a)).margin(1e-3));
    CHECK(corner.z == Approx(295.0f - 165.0f * std::sin(a)).margin(1e-3));
    CHECK(corner.y == Approx(0.0f).margin(1e-3));
}

TEST_CASE("scenes: emission is one-sided unless the material says two_sided", "[scene]") {
    TempDir dir;
    const Scene scene = load_scene(dir.write("s.json", R"({
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
      "film": { "width": 4, "height": 4 },
      "materials": { "one": { "type": "emissive", "emission": [1, 2, 3] },
                     "two": { "type": "emissive", "emission": [1, 2, 3], "two_sided": true } },
      "objects": [] })"));
    REQUIRE(scene.materials.size() == 2);
    CHECK_FALSE(scene.materials[0].two_sided_emission);  // names sort: "one" first
    CHECK(scene.materials[1].two_sided_emission);
    CHECK(scene.materials[1].emission == glm::vec3(1.0f, 2.0f, 3.0f));
}

TEST_CASE("scenes: one OBJ used by two objects is loaded once", "[scene][obj]") {
    TempDir dir;
    dir.write("meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const auto file = dir.write("s.json", R"({
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
      "film": { "width": 4, "height": 4 },
      "materials": { "m": { "type": "diffuse" } },
      "objects": [
        { "type": "mesh", "file": "meshes/tri.obj", "material": "m" },
        { "type": "mesh", "file": "meshes/../meshes/tri.obj", "material": "m", "transform": [{ "translate": [2, 0, 0] }] }
      ]})");
    const Scene scene = load_scene(file);
    REQUIRE(scene.meshes.size() == 1);
    CHECK(scene.meshes[0].triangles.triangle_count() == 1);
    CHECK(std::get<sweeptrace::MeshInstance>(scene.objects[0].shape).mesh == 0);
    CHECK(std::get<sweeptrace::MeshInstance>(scene.objects[1].shape).mesh == 0);
    CHECK_FALSE(scene.objects[1].transform.identity);
}

TEST_CASE("obj: polygons become fans, normals kept, and split where a vertex has two", "[scene][obj]") {
    TempDir dir;
    // A unit square as one quad whose corners carry two different normals at vertex 1.
    const auto file = dir.write("quad.obj",
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "vn 0 0 2\nvn 0 0.6 0.8\n"
                                "f 1//1 2//1 3//1 4//1\n"
                                "f 1//2 3//2 4//2\n");
    const auto mesh = load_obj(file);
    CHECK(mesh.triangles.triangle_count() == 3);
    // Vertices 1, 3 and 4 are each used with two normals: 4 + 3 = 7 distinct pairs.
    REQUIRE(mesh.triangles.vertices.size() == 7);
    REQUIRE(mesh.vertex_normals.size() == 7);
    for (const auto& n : mesh.vertex_normals) CHECK(glm::length(n) == Approx(1.0f).epsilon(1e-6));
    // Fan order keeps the winding: first triangle is (1, 2, 3) with normal +z.
    const collision::Triangle t = mesh.triangles.triangle(0);
    CHECK(glm::cross(t.b - t.a, t.c - t.a).z > 0.0f);

    // One corner without a normal: no smooth shading at all, and shared vertices are not split.
    const auto partial = load_obj(dir.write("partial.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\n"
                                                            "f 1//1 2//1 3//1\nf 2 4 3\n"));
    CHECK(partial.vertex_normals.empty());
    CHECK(partial.triangles.vertices.size() == 4);
    CHECK(partial.triangles.triangle_count() == 2);
}

TEST_CASE("obj: the shared test meshes load with their documented triangle counts", "[scene][obj]") {
    if (!sweeptrace::test::shared_meshes_available()) return;
    const std::filesystem::path meshes = sweeptrace::test::shared_meshes_dir();
    REQUIRE(std::filesystem::exists(meshes / "spot.obj"));
    CHECK(load_obj(meshes / "spot.obj").triangles.triangle_count() == 5856);
    CHECK(load_obj(meshes / "suzanne.obj").triangles.triangle_count() == 968);
    CHECK(load_obj(meshes / "fandisk.obj").triangles.triangle_count() == 12946);
}

TEST_CASE("scenes: primitives has every shape and every material, each object transformed", "[scene]") {
    const Scene scene = load_scene(kScenes / "primitives.json");
    CHECK(count_shapes<collision::Sphere>(scene) == 1);
    CHECK(count_shapes<collision::Aabb>(scene) == 1);
    CHECK(count_shapes<collision::Cylinder>(scene) == 1);
    CHECK(count_shapes<collision::Capsule>(scene) == 1);
    CHECK(count_shapes<collision::Ellipsoid>(scene) == 1);
    CHECK(count_shapes<collision::Disk>(scene) == 1);
    CHECK(count_shapes<collision::Triangle>(scene) == 1);
    CHECK(count_shapes<sweeptrace::MeshInstance>(scene) == 1);
    CHECK(count_shapes<collision::Quad>(scene) == 2);  // the floor too
    for (auto type : {Material::Type::Diffuse, Material::Type::Metal, Material::Type::Dielectric, Material::Type::Emissive})
        CHECK(uses_material_type(scene, type));
    for (const auto& o : scene.objects) {
        INFO(o.name);
        // Rotated and non-uniformly scaled: the linear part is not a multiple of a rotation.
        if (o.name != "floor") CHECK_FALSE(o.transform.identity);
    }
}

TEST_CASE("scenes: the mesh scene instances the project's torus knot twice from one load", "[scene][obj]") {
    const Scene scene = load_scene(kScenes / "mesh.json");
    REQUIRE(scene.meshes.size() == 1);
    CHECK(count_shapes<sweeptrace::MeshInstance>(scene) == 2);
    const auto& knot = scene.meshes[0];
    CHECK(knot.triangles.triangle_count() == 17920);
    CHECK(knot.vertex_normals.size() == knot.triangles.vertices.size());
}

TEST_CASE("scenes: the committed torus knot is closed and wound outward", "[scene][obj]") {
    const auto knot = load_obj(kScenes / "meshes" / "torus_knot.obj");
    // Closed: every undirected edge is shared by exactly two triangles, once in each direction.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& f : knot.triangles.indices)
        for (int k = 0; k < 3; ++k) ++directed[{f[k], f[(k + 1) % 3]}];
    std::size_t unpaired = 0;
    for (const auto& [edge, count] : directed)
        if (count != 1 || directed.count({edge.second, edge.first}) != 1) ++unpaired;
    CHECK(directed.size() == 3 * knot.triangles.triangle_count());
    CHECK(unpaired == 0);
    // Wound counter-clockwise seen from outside: face normals agree with the vertex normals.
    std::size_t inward = 0;
    for (std::size_t i = 0; i < knot.triangles.triangle_count(); ++i) {
        const auto& f = knot.triangles.indices[i];
        const collision::Triangle t = knot.triangles.triangle(i);
        const glm::vec3 n = knot.vertex_normals[f.x] + knot.vertex_normals[f.y] + knot.vertex_normals[f.z];
        if (glm::dot(glm::cross(t.b - t.a, t.c - t.a), n) <= 0.0f) ++inward;
    }
    CHECK(inward == 0);
}

TEST_CASE("scenes: the showcase uses glass, metal, diffuse, a light and the mesh", "[scene]") {
    const Scene scene = load_scene(kScenes / "default.json");
    for (auto type : {Material::Type::Diffuse, Material::Type::Metal, Material::Type::Dielectric, Material::Type::Emissive})
        CHECK(uses_material_type(scene, type));
    CHECK(scene.meshes.size() == 1);
    CHECK(scene.background.kind == sweeptrace::Background::Kind::Sky);
}

TEST_CASE("scenes: the material showcase uses rough glass, plastic, a textured mesh and an environment", "[scene]") {
    const Scene scene = load_scene(kScenes / "showcase.json");
    for (auto type : {Material::Type::RoughDielectric, Material::Type::CoatedDiffuse, Material::Type::Metal})
        CHECK(uses_material_type(scene, type));
    CHECK(scene.background.kind == sweeptrace::Background::Kind::Environment);
    REQUIRE(scene.meshes.size() == 1);
    CHECK(scene.meshes[0].vertex_uvs.size() == scene.meshes[0].triangles.vertices.size());
    CHECK(scene.meshes[0].vertex_normals.size() == scene.meshes[0].triangles.vertices.size());
    bool textured_mesh = false;
    for (const auto& o : scene.objects)
        textured_mesh = textured_mesh || (std::holds_alternative<sweeptrace::MeshInstance>(o.shape) && scene.materials[o.material].albedo_texture >= 0);
    CHECK(textured_mesh);
}

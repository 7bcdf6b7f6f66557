// OBJ materials (scene/load_mtl.hpp, scene/obj_materials.hpp): an OBJ's mtllib / usemtl mapped by
// the README's table, a mesh object split into one object per material, a square of two
// differently coloured triangles rendering each triangle's albedo x L at every pixel (both
// accels), the scene's `material` overriding the .mtl (which is then not read), map_Bump read as a
// height map (its slope tilting the normal as the displaced surface's) or, coloured, a normal map,
// and the errors naming the OBJ or .mtl file and line.
#include <catch2/catch.hpp>

#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "convergence_harness.hpp"
#include "plane_truth.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/materials/texture.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

const char* kSquareObj = "mtllib square.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                         "usemtl dark\nf 1/1 2/2 3/3\nusemtl light\nf 1/1 3/3 4/4\n";

std::string scene_with(const std::string& object) {
    return R"({ "camera": { "position": [0, 0, 3], "look_at": [0, 0, 0], "fov": 50 }, "film": { "width": 32, "height": 32 },
        "background": { "color": [1, 0.8, 0.6] }, "materials": { "grey": { "type": "diffuse" } },
        "objects": [ )" + object + R"( ] })";
}

const Material& named(const Scene& s, const std::string& name) {
    for (const Material& m : s.materials)
        if (m.name == name) return m;
    FAIL("no material " << name);
    return s.materials[0];
}

std::string load_error(const std::filesystem::path& file) {
    try {
        load_scene(file);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(loaded)";
}

}  // namespace

TEST_CASE("obj materials: the mtl table", "[scene][obj_materials]") {
    test::TempDir dir;
    dir.write("all.obj", "mtllib all.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
                         "f 1/1 2/2 3/3\nusemtl clay\nf 2/2 4/4 3/3\nusemtl steel\nf 1/1 2/2 3/3\nusemtl glass\nf 1/1 2/2 3/3\n"
                         "usemtl lamp\nf 1/1 2/2 3/3\nusemtl wood\nf 1/1 2/2 3/3\n");
    write_image(Image(2, 2), dir.path() / "wood.png");
    dir.write("all.mtl", "# a comment\nnewmtl clay\nKa 0.1 0.1 0.1\nKd 0.5 0.4 0.3\nKs 0.2 0.2 0.2\nNs 10\nillum 2\n"
                         "newmtl steel\nKd 0 0 0\nKs 0.9 0.8 0.7\nNs 98\nillum 3\n"
                         "newmtl glass\nKd 0.1 0.1 0.1\nNi 1.33\nd 0.2\nillum 4\n"
                         "newmtl lamp\nKd 0 0 0\nKe 5 4 3\n"
                         "newmtl wood\nKd 1 1 1\nmap_Kd -bm 1.0 wood.png\nnorm wood.png\n");
    const Scene s = load_scene(dir.write("s.json", scene_with(R"({ "type": "mesh", "file": "all.obj", "name": "m" })")));
    REQUIRE(s.objects.size() == 6);  // the faces before any usemtl, and one per material
    const Material& clay = named(s, "all.mtl/clay");
    CHECK(clay.type == Material::Type::CoatedDiffuse);  // Kd and Ks: a coat over a diffuse base
    CHECK(clay.albedo == glm::vec3(0.5f, 0.4f, 0.3f));
    CHECK(clay.ior == 1.5f);  // no Ni
    CHECK(clay.roughness == Approx(std::pow(2.0 / 12.0, 0.25)));
    const Material& steel = named(s, "all.mtl/steel");
    CHECK(steel.type == Material::Type::Metal);
    CHECK(steel.albedo == glm::vec3(0.9f, 0.8f, 0.7f));
    CHECK(steel.roughness == Approx(std::pow(2.0 / 100.0, 0.25)));  // alpha = sqrt(2 / (Ns + 2)) = roughness^2
    const Material& glass = named(s, "all.mtl/glass");
    CHECK(glass.type == Material::Type::Dielectric);
    CHECK(glass.ior == 1.33f);
    CHECK(named(s, "all.mtl/lamp").emission == glm::vec3(5.0f, 4.0f, 3.0f));
    CHECK(named(s, "all.mtl/lamp").type == Material::Type::Diffuse);  // no Ks
    const Material& wood = named(s, "all.mtl/wood");
    REQUIRE(wood.albedo_texture >= 0);
    REQUIRE(wood.normal_texture >= 0);
    CHECK_FALSE(s.textures[wood.albedo_texture].linear_data);
    CHECK(s.textures[wood.normal_texture].linear_data);
    CHECK(named(s, "all.obj (faces before any usemtl)").albedo == glm::vec3(0.8f));
    // Each part holds its own triangles: 1 + 1 + 1 + 1 + 1 + 1 of the six faces.
    std::size_t triangles = 0;
    for (const Object& o : s.objects) triangles += s.meshes[std::get<MeshInstance>(o.shape).mesh].triangles.indices.size();
    CHECK(triangles == 6);

    // The scene's material overrides: one object, and the .mtl is not even read.
    std::filesystem::remove(dir.path() / "all.mtl");
    const Scene o = load_scene(dir.write("o.json", scene_with(R"({ "type": "mesh", "file": "all.obj", "material": "grey" })")));
    CHECK(o.objects.size() == 1);
}

TEST_CASE("obj materials: a square of two materials renders each triangle's albedo x L", "[render][obj_materials]") {
    test::TempDir dir;
    dir.write("square.obj", kSquareObj);
    dir.write("square.mtl", "newmtl dark\nKd 0.2 0.3 0.4\nnewmtl light\nKd 0.9 0.7 0.5\n");
    Scene scene = load_scene(dir.write("s.json", scene_with(R"({ "type": "mesh", "file": "square.obj", "materials": "from_obj" })")));
    REQUIRE(scene.objects.size() == 2);
    const glm::vec3 L(1.0f, 0.8f, 0.6f), dark(0.2f, 0.3f, 0.4f), light(0.9f, 0.7f, 0.5f);
    const PlaneTruth truth = plane_truth(
        32, 8,
        [](double wx, double wy) {
            const bool on = std::abs(wx) < 1 && std::abs(wy) < 1;
            return on ? (wy < wx ? 0 : 1) : 2;  // face 1 (dark) is below the diagonal
        },
        [&](int cell) { return cell == 2 ? L : (cell == 0 ? dark : light) * L; });
    check_plane_render(scene, truth);
}

TEST_CASE("obj materials: errors name the OBJ or .mtl file and line", "[scene][obj_materials]") {
    test::TempDir dir;
    dir.write("square.obj", kSquareObj);
    const auto scene = dir.write("s.json", scene_with(R"({ "type": "mesh", "file": "square.obj" })"));
    CHECK_THAT(load_error(scene), Catch::Contains("objects[0].file: ") &&
                                      Catch::Contains("square.obj: line 1: mtllib \"square.mtl\" not found"));
    dir.write("square.mtl", "newmtl dark\nKd 0.2 0.3 0.4\nnewmtl light\nKd 0.9 x 0.5\n");
    CHECK_THAT(load_error(scene), Catch::Contains("square.mtl: line 4: Kd 'x' is not a decimal number"));
    dir.write("square.mtl", "newmtl dark\nKd 0.2 0.3 0.4\nnewmtl light\nKd 0.9 0.7 1.5\n");
    CHECK_THAT(load_error(scene), Catch::Contains("square.mtl: line 4: Kd 1.5 is out of range"));
    dir.write("square.mtl", "newmtl dark\nKd 0.2 0.3 0.4\n");
    CHECK_THAT(load_error(scene), Catch::Contains("square.obj: line 12: usemtl \"light\": no such material"));
    dir.write("square.mtl", "newmtl dark\nnewmtl light\n\nmap_Kd -s 1 1 1 nothere.png\n");
    CHECK_THAT(load_error(scene), Catch::Contains("square.mtl: line 4: map_Kd: texture image \"nothere.png\" not found"));
    dir.write("novt.obj", "mtllib square.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl light\nf 1 2 3\n");
    CHECK_THAT(load_error(dir.write("n.json", scene_with(R"({ "type": "mesh", "file": "novt.obj" })"))),
               Catch::Contains("square.mtl: line 4: map_Kd: a texture needs texture coordinates"));
    dir.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK_THAT(load_error(dir.write("p.json", scene_with(R"({ "type": "mesh", "file": "plain.obj" })"))),
               Catch::Contains("plain.obj: names no material library (no mtllib line): give the object a \"material\""));
    CHECK_THAT(load_error(dir.write("b.json", scene_with(R"({ "type": "mesh", "file": "plain.obj", "material": "grey", "materials": "from_obj" })"))),
               Catch::Contains("objects[0]: give either \"material\""));
    CHECK_THAT(load_error(dir.write("v.json", scene_with(R"({ "type": "mesh", "file": "plain.obj", "materials": "mine" })"))),
               Catch::Contains("objects[0].materials: the only value is \"from_obj\""));
    CHECK_THAT(load_error(dir.write("q.json", scene_with(R"({ "type": "sphere", "radius": 1, "materials": "from_obj" })"))),
               Catch::Contains("objects[0].materials: unknown key"));
}

TEST_CASE("obj materials: map_Bump is a height map when grey, a normal map when coloured", "[render][obj_materials]") {
    test::TempDir dir;
    dir.write("square.obj", kSquareObj);
    // A ramp in u: texel x holds the 8-bit code 36 x (read back as exactly 36 x / 255, a data
    // map), so between texel centres dh/du = 8 x 36 / 255. (write_image encodes to sRGB.)
    Image ramp(8, 1);
    for (int x = 0; x < 8; ++x) ramp.at(x, 0) = glm::vec3(srgb_decode(static_cast<float>(36 * x) / 255.0f));
    write_image(ramp, dir.path() / "ramp.png");
    Image normals(2, 2);
    for (glm::vec3& p : normals.pixels) p = glm::vec3(0.5f, 0.5f, 1.0f);
    write_image(normals, dir.path() / "n.png");
    dir.write("square.mtl", "newmtl dark\nKd 0.5 0.5 0.5\nmap_Bump -bm 0.25 ramp.png\n"
                            "newmtl light\nKd 0.5 0.5 0.5\nbump -s 1 1 1 -bm 0.25 ramp.png\n");
    const auto file = dir.write("s.json", scene_with(R"({ "type": "mesh", "file": "square.obj" })"));
    const Scene scene = load_scene(file);
    for (const char* name : {"square.mtl/dark", "square.mtl/light"}) {
        const Material& m = named(scene, name);
        INFO(name);
        REQUIRE(m.bump_texture >= 0);
        CHECK(m.normal_texture < 0);
        CHECK(m.bump_scale == 0.25f);
        CHECK(scene.textures[m.bump_texture].linear_data);
    }
    // The shading normal where a ray meets the square (the uv map takes (-1, -1) .. (1, 1) to
    // [0, 1]^2, so dpdu = (2, 0, 0), dpdv = (0, 2, 0)): the ramp's displaced surface's normal.
    const auto accel = make_accel(AccelKind::Bvh, scene);
    for (const glm::vec2 at : {glm::vec2(0.1f, 0.3f), glm::vec2(-0.2f, -0.3f)}) {  // one point on each triangle
        SurfaceHit hit;
        REQUIRE(accel->intersect(collision::Ray{glm::vec3(at, 3.0f), glm::vec3(0.0f, 0.0f, -1.0f)}, hit));
        const Material& base = scene.materials[scene.objects[hit.object].material];
        (void)textured_material(scene, base, hit);
        const float slope = 0.25f * 8.0f * 36.0f / 255.0f;
        const glm::vec3 expected = glm::normalize(glm::cross(glm::vec3(2.0f, 0.0f, slope), glm::vec3(0.0f, 2.0f, 0.0f)));
        INFO("at " << at.x << ", " << at.y << ": " << hit.shading_normal.x << " " << hit.shading_normal.y << " " << hit.shading_normal.z);
        CHECK(glm::length(hit.shading_normal - expected) < 1e-4f);
    }

    // A coloured image in map_Bump is a normal map (what Blender's exporter writes there).
    dir.write("square.mtl", "newmtl dark\nmap_Bump -bm 1.0 n.png\nnewmtl light\nnorm n.png\n");
    const Scene colour = load_scene(file);
    for (const char* name : {"square.mtl/dark", "square.mtl/light"}) {
        INFO(name);
        CHECK(named(colour, name).normal_texture >= 0);
        CHECK(named(colour, name).bump_texture < 0);
    }
    // A grey one beside norm: both apply.
    dir.write("square.mtl", "newmtl dark\nnorm n.png\nbump ramp.png\nnewmtl light\n");
    const Scene both = load_scene(file);
    CHECK(named(both, "square.mtl/dark").normal_texture >= 0);
    CHECK(named(both, "square.mtl/dark").bump_texture >= 0);
    CHECK(named(both, "square.mtl/dark").bump_scale == 1.0f);

    // Errors name the file, the line and the statement.
    const std::pair<const char*, const char*> errors[] = {
        {"newmtl dark\nnorm n.png\nmap_Bump n.png\nnewmtl light\n",
         "square.mtl: line 3: bump map: a coloured image (a normal map) where norm already gives one"},
        {"newmtl dark\nmap_Bump -bm ramp.png\nnewmtl light\n", "square.mtl: line 2: map_Bump -bm needs a number before the file"},
        {"newmtl dark\nnewmtl light\nbump -bm x ramp.png\n", "square.mtl: line 3: bump -bm 'x' is not a decimal number"}};
    for (const auto& [mtl, message] : errors) {
        dir.write("square.mtl", mtl);
        CHECK_THAT(load_error(file), Catch::Contains(message));
    }
    // -bm means nothing to the other maps: read past, as before.
    dir.write("square.mtl", "newmtl dark\nmap_Kd -bm x n.png\nnewmtl light\n");
    CHECK(named(load_scene(file), "square.mtl/dark").albedo_texture >= 0);
}

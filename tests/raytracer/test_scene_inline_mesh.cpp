// Mesh objects given inline (scene/inline_mesh.hpp): the same mesh as from a file, hit for hit,
// uv for uv and with the same shading normals; each malformed array refused with its JSON path.
// And the pbrt importer's trianglemesh written as one: its uv, its normals, pbrt's default uv.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "pbrt_test_support.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/materials/texture.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_load_error.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using sweeptrace::test::TempDir;
using nlohmann::json;

namespace {

const std::string kHead = R"({"camera": {"position": [0, 0.5, 4], "look_at": [0, 0.3, 0]}, "film": {"width": 8, "height": 8},
    "materials": {"m": {"type": "diffuse"}, "t": {"type": "diffuse", "albedo": {"checker": {"a": [1, 1, 1], "b": [0, 0, 0], "scale": 4}}}},
    "objects": [)";

std::string scene_with(const std::string& object) { return kHead + object + "]}"; }

// A bent strip of four triangles: smooth normals that differ from the faces', uv over [0, 2].
const char* kObj = "v -1 0 0\nv 0 0 -0.3\nv 1 0 0\nv -1 1 0\nv 0 1 -0.3\nv 1 1 0\n"
                   "vt 0 0\nvt 1 0\nvt 2 0\nvt 0 1\nvt 1 1\nvt 2 1\n"
                   "vn -0.3 0 1\nvn 0 0 1\nvn 0.3 0 1\nvn -0.3 0 1\nvn 0 0 1\nvn 0.3 0 1\n"
                   "f 1/1/1 2/2/2 5/5/5\nf 1/1/1 5/5/5 4/4/4\nf 2/2/2 3/3/3 6/6/6\nf 2/2/2 6/6/6 5/5/5\n";
const char* kInline = R"({"type": "mesh", "material": "t", "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 20}}],
    "vertices": [-1, 0, 0,  0, 0, -0.3,  1, 0, 0,  -1, 1, 0,  0, 1, -0.3,  1, 1, 0],
    "indices": [0, 1, 4,  0, 4, 3,  1, 2, 5,  1, 5, 4],
    "normals": [-0.3, 0, 1,  0, 0, 1,  0.3, 0, 1,  -0.3, 0, 1,  0, 0, 1,  0.3, 0, 1],
    "uvs": [0, 0,  1, 0,  2, 0,  0, 1,  1, 1,  2, 1]})";

}  // namespace

TEST_CASE("inline mesh: the same mesh as its OBJ file, hit for hit, with the same uv and shading normals", "[scene][mesh]") {
    const TempDir dir;
    dir.write("strip.obj", kObj);
    const Scene a = load_scene(dir.write("a.json", scene_with(kInline)));
    const Scene b = load_scene(dir.write("b.json", scene_with(R"({"type": "mesh", "file": "strip.obj", "material": "t",
        "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 20}}]})")));
    REQUIRE(a.meshes.size() == 1);
    CHECK(a.meshes[0].triangles.indices.size() == 4);
    CHECK(glm::length(a.meshes[0].vertex_normals[0]) == Approx(1.0f));
    for (const AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
        const auto accel_a = make_accel(kind, a), accel_b = make_accel(kind, b);
        Rng rng(3, 0, 0);
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            collision::Ray ray;
            ray.origin = {rng.uniform() * 4.0f - 2.0f, rng.uniform() * 3.0f - 1.0f, 3.0f};
            ray.dir = glm::normalize(glm::vec3(rng.uniform() * 2.4f - 1.2f, rng.uniform() * 1.4f - 0.2f, -0.2f) - ray.origin);
            SurfaceHit ha, hb;
            const bool ia = accel_a->intersect(ray, ha), ib = accel_b->intersect(ray, hb);
            REQUIRE(ia == ib);
            if (!ia) continue;
            ++hits;
            CHECK(ha.t == hb.t);
            CHECK(ha.normal == hb.normal);
            CHECK(ha.shading_normal == hb.shading_normal);
            CHECK(hit_uv(a, ha) == hit_uv(b, hb));
        }
        CHECK(hits > 1000);
    }
}

TEST_CASE("inline mesh: malformed arrays are refused with their JSON path", "[scene][mesh][errors]") {
    const TempDir dir;
    using sweeptrace::test::load_error;
    auto mesh = [](const std::string& keys) { return scene_with(R"({"type": "mesh", "material": "m", )" + keys + "}"); };
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0], "indices": [0, 1, 2])")),
               Catch::Contains("objects[0].vertices: must hold 3 numbers per vertex (a multiple of 3, at least 3), got 5"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, "a", 0], "indices": [0, 1, 2])")),
               Catch::Contains("objects[0].vertices[7]: must be a number"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, 1e39, 0], "indices": [0, 1, 2])")),
               Catch::Contains("objects[0].vertices[7]: is too large for single precision"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 3])")),
               Catch::Contains("objects[0].indices[2]: must be in [0, 2], got 3"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, -1])")),
               Catch::Contains("objects[0].indices[2]: must be in [0, 2], got -1"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1])")),
               Catch::Contains("objects[0].indices: must hold 3 vertex numbers per triangle"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2], "normals": [0, 0, 1, 0, 0, 0, 0, 0, 1])")),
               Catch::Contains("objects[0].normals: normal 1 (elements 3 to 5) has no direction"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2], "normals": [0, 0, 1])")),
               Catch::Contains("objects[0].normals: must give one normal per vertex: 1 for 3 vertices"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2], "uvs": [0, 0, 1, 0])")),
               Catch::Contains("objects[0].uvs: must give one (u, v) per vertex: 2 for 3 vertices"));
    CHECK_THAT(load_error(dir, mesh(R"("vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0])")), Catch::Contains("objects[0].indices: missing (required)"));
    CHECK_THAT(load_error(dir, mesh(R"("indices": [0, 1, 2])")),
               Catch::Contains("objects[0]: a mesh needs a \"file\" (OBJ or PLY) or its \"vertices\" and \"indices\" inline"));
    dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK_THAT(load_error(dir, mesh(R"("file": "m.obj", "vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2])")),
               Catch::Contains("objects[0].vertices: a mesh is either a \"file\" or given inline"));
    // No materials of its own, and no uv unless given.
    CHECK_THAT(load_error(dir, scene_with(R"({"type": "mesh", "materials": "from_obj", "vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2]})")),
               Catch::Contains("objects[0].materials: an inline mesh has no materials of its own"));
    CHECK_THAT(load_error(dir, scene_with(R"({"type": "mesh", "material": "t", "vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2]})")),
               Catch::Contains("objects[0].material: material \"t\" reads a texture, but this mesh has no uv coordinates"));
}

TEST_CASE("pbrt trianglemesh: one inline mesh with pbrt's uv and normals, or pbrt's default uv per triangle", "[pbrt][mesh]") {
    const TempDir dir;
    sweeptrace::Image tex(4, 4);
    sweeptrace::write_image(tex, dir.path() / "t.png");
    const std::string head = "WorldBegin\nTexture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"t.png\"\n"
                             "Material \"diffuse\" \"texture reflectance\" \"t\"\n";
    // A floor quad with uv 0..5, as pbrt-v4's killeroo scenes have.
    const std::string floor = "Shape \"trianglemesh\" \"point2 uv\" [0 0 5 0 5 5 0 5] \"integer indices\" [0 1 2 2 3 0]\n"
                              "  \"point3 P\" [-4 -4 0 4 -4 0 4 4 0 -4 4 0] \"normal N\" [0 0 1 0 0 1 0 0 1 0 0 1]\n";
    const auto c = sweeptrace::test::convert_text(dir, head + floor);
    CHECK(c.warnings.empty());
    const json& o = c.doc["objects"][0];
    CHECK(o["uvs"] == json({0.0, 0.0, 5.0, 0.0, 5.0, 5.0, 0.0, 5.0}));
    CHECK(o["normals"] == json({0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0}));
    // The uv at a point is pbrt's, interpolated: (1, 1) on the floor is (3.125, 3.125).
    {
        std::vector<std::string> warnings;
        const Scene s = load_pbrt_scene(dir.write("scene.pbrt", head + floor), false, warnings);
        const auto accel = make_accel(AccelKind::Bvh, s);
        collision::Ray ray;
        ray.origin = {1.0f, 1.0f, 3.0f};
        ray.dir = {0.0f, 0.0f, -1.0f};
        SurfaceHit h;
        REQUIRE(accel->intersect(ray, h));
        const glm::vec2 uv = hit_uv(s, h);
        CHECK(uv.x == Approx(3.125f));
        CHECK(uv.y == Approx(3.125f));
        CHECK(h.shading_normal.z == Approx(1.0f));
    }
    // No uv and a texture: pbrt's (0, 0), (1, 0), (1, 1) at each triangle's corners, vertices unshared.
    const auto d = sweeptrace::test::convert_text(dir, head + "Shape \"trianglemesh\" \"integer indices\" [0 1 2 2 3 0]\n"
                                                              "  \"point3 P\" [-4 -4 0 4 -4 0 4 4 0 -4 4 0]\n");
    const json& q = d.doc["objects"][0];
    CHECK(q["indices"] == json({0, 1, 2, 3, 4, 5}));
    CHECK(q["uvs"] == json({0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0}));
    CHECK(q["vertices"].size() == 18);
    // Normals decide the front: given against the winding, the triangle is turned to face them.
    const auto e = sweeptrace::test::convert_text(dir, "WorldBegin\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] "
                                                       "\"integer indices\" [0 1 2] \"normal N\" [0 0 -1 0 0 -1 0 0 -1]\n");
    CHECK(e.doc["objects"][0]["indices"] == json({0, 2, 1}));
    CHECK(e.doc["objects"][0]["normals"][2] == -1.0);
}

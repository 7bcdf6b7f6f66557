// A farm part's scene identity (cli/render_identity.hpp) covers every input of the render, not
// only the scene and mesh files: a material library or an image that changes between parts
// must make merge refuse them.
#include <catch2/catch.hpp>

#include "raytracer/cli/render_identity.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;

TEST_CASE("farm identity: changing a .mtl, a texture image or the environment image changes the scene hash",
          "[farm]") {
    test::TempDir dir;
    dir.write("square.obj", "mtllib square.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                            "usemtl painted\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    dir.write("square.mtl", "newmtl painted\nKd 0.5 0.5 0.5\nmap_Kd paint.png\n");
    Image paint(2, 2);
    write_image(paint, dir.path() / "paint.png");
    Image sky(4, 2);
    for (auto& p : sky.pixels) p = glm::vec3(1.0f);
    write_image(sky, dir.path() / "sky.pfm");
    const auto scene_file = dir.write("s.json", R"({ "camera": { "position": [0, 0, 3], "look_at": [0, 0, 0] }, "film": { "width": 8, "height": 8 }, "materials": { "grey": { "type": "diffuse" } },
        "background": { "environment": { "file": "sky.pfm" } },
        "objects": [ { "type": "mesh", "file": "square.obj" } ] })");
    const auto hash = [&] { return scene_content_hash(load_scene(scene_file), scene_file); };
    const std::string original = hash();
    CHECK(hash() == original);  // the same files, the same hash

    dir.write("square.mtl", "newmtl painted\nKd 0.6 0.5 0.5\nmap_Kd paint.png\n");
    const std::string after_mtl = hash();
    CHECK(after_mtl != original);

    paint.at(1, 1) = glm::vec3(1.0f);
    write_image(paint, dir.path() / "paint.png");
    const std::string after_texture = hash();
    CHECK(after_texture != after_mtl);

    sky.at(0, 0) = glm::vec3(2.0f);
    write_image(sky, dir.path() / "sky.pfm");
    CHECK(hash() != after_texture);
}

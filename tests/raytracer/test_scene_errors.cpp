// Bad scene input: every case must throw InputError whose message names the file and points at
// the culprit (JSON path, or line:column for text that is not JSON).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_load_error.hpp"
#include "scene_test_files.hpp"

using sweeptrace::InputError;
using sweeptrace::load_scene;
using sweeptrace::test::TempDir;

namespace {

const char* const kMaterials = R"({ "m": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5] } })";

// A valid scene around the given pieces, so each case changes exactly one thing.
std::string scene_text(const std::string& objects, const std::string& materials = kMaterials,
                       const std::string& film = R"({ "width": 8, "height": 6 })",
                       const std::string& camera = R"({ "position": [0, 0, 5], "look_at": [0, 0, 0] })",
                       const std::string& extra = "") {
    return "{\n  \"camera\": " + camera + ",\n  \"film\": " + film + ",\n  \"materials\": " + materials +
           ",\n" + extra + "  \"objects\": " + objects + "\n}\n";
}

const char* const kSphere = R"([{ "type": "sphere", "radius": 1, "material": "m" }])";

using sweeptrace::test::load_error;

}  // namespace

TEST_CASE("scene errors: the valid base scene loads", "[scene][errors]") {
    TempDir dir;
    const auto scene = load_scene(dir.write("ok.json", scene_text(kSphere)));
    CHECK(scene.objects.size() == 1);
    CHECK(scene.materials.size() == 1);
}

TEST_CASE("scene errors: missing file and invalid JSON with line and column", "[scene][errors]") {
    TempDir dir;
    try {
        load_scene(dir.path() / "nothere.json");
        FAIL("missing file loaded");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("nothere.json") && Catch::Contains("no such file"));
    }
    // The stray comma is on line 3, column 12.
    CHECK_THAT(load_error(dir, "{\n  \"camera\": {\n    \"fov\": ,\n"), Catch::Contains("bad.json:3:12: invalid JSON"));
    // JSON has no NaN literal: a NaN can only arrive as text, which is a syntax error with its place.
    CHECK_THAT(load_error(dir, "{\n \"seed\": NaN }"), Catch::Contains("bad.json:2:") && Catch::Contains("invalid JSON"));
    CHECK_THAT(load_error(dir, ""), Catch::Contains("bad.json:1:1: invalid JSON"));
}

TEST_CASE("scene errors: numbers that are not finite, or not finite in float", "[scene][errors]") {
    TempDir dir;
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": 1e999, "material": "m" }])")),
               Catch::Contains("bad.json:5:45: number 1e999 is out of range"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": 1e39, "material": "m" }])")),
               Catch::Contains("objects[0].radius: is too large for single precision"));
}

TEST_CASE("scene errors: unknown keys, shapes and material types name their JSON path", "[scene][errors]") {
    TempDir dir;
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6 })",
                                          R"({ "position": [0, 0, 5], "look_at": [0, 0, 0] })", "  \"camra\": {},\n")),
               Catch::Contains("bad.json: camra: unknown key"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": 1, "material": "m" },
        { "type": "box", "size": [1, 1, 1], "radius": 2, "material": "m" }])")),
               Catch::Contains("objects[1].radius: unknown key") && Catch::Contains("allowed here:"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "torus", "radius": 1, "material": "m" }])")),
               Catch::Contains("objects[0].type: unknown shape type \"torus\""));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "m": { "type": "plastic" } })")),
               Catch::Contains("materials.m.type: unknown material type \"plastic\""));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "m": { "type": "diffuse", "ior": 1.5 } })")),
               Catch::Contains("materials.m.ior: unknown key"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": 1, "material": "m", "transform": [{ "shear": 1 }] }])")),
               Catch::Contains("objects[0].transform[0].shear: unknown key"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": 1, "radius": 2, "material": "m" }])")),
               Catch::Contains("objects[0].radius: duplicate key"));
}

TEST_CASE("scene errors: wrong JSON types", "[scene][errors]") {
    TempDir dir;
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": "big", "material": "m" }])")),
               Catch::Contains("objects[0].radius: must be a number, got a string"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "center": [1, 2], "radius": 1, "material": "m" }])")),
               Catch::Contains("objects[0].center: must be an array of 3 numbers"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "center": [1, true, 2], "radius": 1, "material": "m" }])")),
               Catch::Contains("objects[0].center[1]: must be a number, got a boolean"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 8.5, "height": 6 })")),
               Catch::Contains("film.width: must be an integer, got 8.5"));
    CHECK_THAT(load_error(dir, scene_text(R"({ "type": "sphere" })")),
               Catch::Contains("objects: must be an array, got an object"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": 3, "material": "m" }])")),
               Catch::Contains("objects[0].type: must be a string, got a number"));
    CHECK_THAT(load_error(dir, "[1, 2]"), Catch::Contains("bad.json: (top level): must be an object"));
}

TEST_CASE("scene errors: sizes, ranges and degenerate geometry", "[scene][errors]") {
    TempDir dir;
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": -1, "material": "m" }])")),
               Catch::Contains("objects[0].radius: must be > 0, got -1"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "cylinder", "radius": 1, "height": 0, "material": "m" }])")),
               Catch::Contains("objects[0].height: must be > 0, got 0"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "ellipsoid", "radii": [1, 0, 1], "material": "m" }])")),
               Catch::Contains("objects[0].radii[1]: must be > 0, got 0"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "box", "size": [1, -2, 1], "material": "m" }])")),
               Catch::Contains("objects[0].size[1]: must be > 0, got -2"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "box", "min": [0, 0, 0], "max": [1, 1, 0], "material": "m" }])")),
               Catch::Contains("objects[0].max[2]: must be > min[2]"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "box", "center": [0, 0, 0], "min": [0, 0, 0], "max": [1, 1, 1], "material": "m" }])")),
               Catch::Contains("objects[0]: give either \"center\" and \"size\", or \"min\" and \"max\""));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "quad", "corner": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [2, 0, 0], "material": "m" }])")),
               Catch::Contains("objects[0]: edge_u and edge_v must not be parallel"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "triangle", "a": [0, 0, 0], "b": [1, 1, 1], "c": [2, 2, 2], "material": "m" }])")),
               Catch::Contains("objects[0]: a, b and c are collinear"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "disk", "normal": [0, 0, 0], "radius": 1, "material": "m" }])")),
               Catch::Contains("objects[0].normal: must not be the zero vector"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 0, "height": 6 })")),
               Catch::Contains("film.width: must be in [1, 16384], got 0"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6, "spp": 0 })")),
               Catch::Contains("film.spp: must be in [1, "));
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6 })",
                                          R"({ "position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 180 })")),
               Catch::Contains("camera.fov: must be a vertical field of view in degrees"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6 })",
                                          R"({ "position": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 0, 2] })")),
               Catch::Contains("camera.up: must not be parallel to the viewing direction"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6 })",
                                          R"({ "position": [0, 0, 0], "look_at": [0, 0, 0] })")),
               Catch::Contains("camera.look_at: must differ from camera.position"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6 })",
                                          R"({ "position": [0, 0, 5], "look_at": [0, 0, 0], "near_clip": -1 })")),
               Catch::Contains("camera.near_clip: must be"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "m": { "type": "diffuse", "albedo": [0.5, 1.5, 0.5] } })")),
               Catch::Contains("materials.m.albedo[1]: must be in [0, 1], got 1.5"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "m": { "type": "metal", "roughness": -0.1 } })")),
               Catch::Contains("materials.m.roughness: must be in [0, 1]"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "m": { "type": "dielectric", "ior": 0 } })")),
               Catch::Contains("materials.m.ior: must be > 0"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "m": { "type": "emissive", "emission": [1, 1, 1], "two_sided": 1 } })")),
               Catch::Contains("materials.m.two_sided: must be true or false, got a number"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "m": { "type": "emissive" } })")),
               Catch::Contains("materials.m.emission: missing (required)"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "m": { "type": "emissive", "emission": [0, 0, 0] } })")),
               Catch::Contains("materials.m.emission: an emissive material must emit"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6 })",
                                          R"({ "position": [0, 0, 5], "look_at": [0, 0, 0] })", "  \"seed\": -3,\n")),
               Catch::Contains("seed: must be >= 0, got -3"));
}

TEST_CASE("scene errors: material references", "[scene][errors]") {
    TempDir dir;
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": 1, "material": "nope" }])")),
               Catch::Contains("objects[0].material: unknown material \"nope\" (defined: m)"));
    CHECK_THAT(load_error(dir, scene_text(R"([{ "type": "sphere", "radius": 1 }])")),
               Catch::Contains("objects[0].material: missing (required)"));
    CHECK_THAT(load_error(dir, scene_text(kSphere, R"({ "my glass": { "type": "glass" } })")),
               Catch::Contains("materials[\"my glass\"].type: unknown material type"));
}

TEST_CASE("scene errors: transforms", "[scene][errors]") {
    TempDir dir;
    auto with_transform = [](const std::string& steps) {
        return scene_text(R"([{ "type": "sphere", "radius": 1, "material": "m", "transform": )" + steps + " }]");
    };
    CHECK_THAT(load_error(dir, with_transform(R"([{ "translate": [1, 0, 0] }, { "scale": [1, 0, 1] }])")),
               Catch::Contains("objects[0].transform[1].scale[1]: must be > 0, got 0"));
    CHECK_THAT(load_error(dir, with_transform(R"([{ "scale": -2 }])")),
               Catch::Contains("objects[0].transform[0].scale: must be > 0: only a mesh's transform may mirror (a negative scale), got -2"));
    CHECK_THAT(load_error(dir, with_transform(R"([{ "scale": [1, -1, 1] }])")),
               Catch::Contains("objects[0].transform[0].scale[1]: must be > 0: only a mesh's transform may mirror"));
    CHECK_THAT(load_error(dir, with_transform(R"([{ "translate": [1, 0, 0], "scale": 2 }])")),
               Catch::Contains("objects[0].transform[0]: each step has exactly one of"));
    CHECK_THAT(load_error(dir, with_transform(R"([{ "rotate": { "axis": [0, 0, 0], "degrees": 30 } }])")),
               Catch::Contains("objects[0].transform[0].rotate.axis: must not be the zero vector"));
    CHECK_THAT(load_error(dir, with_transform(R"([{ "rotate": { "axis": [0, 1, 0] } }])")),
               Catch::Contains("objects[0].transform[0].rotate.degrees: missing (required)"));
    // Each step is fine; together they underflow float to a singular matrix.
    CHECK_THAT(load_error(dir, with_transform(R"([{ "scale": 1e-30 }, { "scale": 1e-30 }])")),
               Catch::Contains("objects[0].transform: transform is singular"));
}

TEST_CASE("scene errors: OBJ meshes", "[scene][errors]") {
    TempDir dir;
    const std::string mesh_object = R"([{ "type": "mesh", "file": "meshes/m.obj", "material": "m" }])";
    CHECK_THAT(load_error(dir, scene_text(mesh_object)),
               Catch::Contains("objects[0].file: mesh file \"meshes/m.obj\" not found"));

    dir.write("meshes/m.obj", "# only a comment\nv 0 0 0\n");
    CHECK_THAT(load_error(dir, scene_text(mesh_object)),
               Catch::Contains("objects[0].file: ") && Catch::Contains("m.obj: contains no faces"));

    dir.write("meshes/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
    CHECK_THAT(load_error(dir, scene_text(mesh_object)),
               Catch::Contains("m.obj: line 5: vertex index out of range (refers to vertex 4, the file has 3)"));

    dir.write("meshes/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
    CHECK_THAT(load_error(dir, scene_text(mesh_object)), Catch::Contains("m.obj: line 4: vertex index out of range"));

    dir.write("meshes/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n");
    CHECK_THAT(load_error(dir, scene_text(mesh_object)),
               Catch::Contains("m.obj: line 5: normal index out of range (refers to normal 2, the file has 1)"));

    dir.write("meshes/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    CHECK_THAT(load_error(dir, scene_text(mesh_object)), Catch::Contains("m.obj: invalid OBJ") && Catch::Contains("line 4"));

    dir.write("meshes/m.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
    CHECK_THAT(load_error(dir, scene_text(mesh_object)), Catch::Contains("m.obj: line 3: a face needs 3 to 255 vertices, this one has 2"));
}

TEST_CASE("scene errors: lights", "[scene][errors][lights]") {
    TempDir dir;
    auto with_lights = [](const std::string& lights) {
        return scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6 })",
                          R"({ "position": [0, 0, 5], "look_at": [0, 0, 0] })", "  \"lights\": " + lights + ",\n");
    };
    CHECK(load_scene(dir.write("ok.json", with_lights(R"([{ "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1] }])")))
              .lights.size() == 1);
    CHECK_THAT(load_error(dir, with_lights(R"([{ "type": "area" }])")),
               Catch::Contains("lights[0].type: unknown light type \"area\" (known: point, spot, directional)"));
    CHECK_THAT(load_error(dir, with_lights(R"([{ "type": "point", "intensity": [1, 1, 1] }])")),
               Catch::Contains("lights[0].position: missing (required)"));
    CHECK_THAT(load_error(dir, with_lights(R"([{ "type": "point", "position": [0, 2, 0], "intensity": [0, 0, 0] }])")),
               Catch::Contains("lights[0].intensity: a light must emit"));
    CHECK_THAT(load_error(dir, with_lights(R"([{ "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1], "radius": 1 }])")),
               Catch::Contains("lights[0].radius"));
    const char* const spot = R"([{ "type": "spot", "position": [0, 2, 0], "intensity": [1, 1, 1], "direction": [0, -1, 0], )";
    CHECK_THAT(load_error(dir, with_lights(std::string(spot) + R"("cone_angle": 0 }])")),
               Catch::Contains("lights[0].cone_angle: must be a half-angle in degrees in (0, 90], got 0"));
    CHECK_THAT(load_error(dir, with_lights(std::string(spot) + R"("cone_angle": 30, "falloff_start": 40 }])")),
               Catch::Contains("lights[0].falloff_start: must be in [0, 30], got 40"));
    CHECK_THAT(load_error(dir, with_lights(R"([{ "type": "directional", "direction": [0, 0, 0], "irradiance": [1, 1, 1] }])")),
               Catch::Contains("lights[0].direction: must not be the zero vector"));
    CHECK_THAT(load_error(dir, with_lights(R"([{ "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1], "angular_diameter": 120 }])")),
               Catch::Contains("lights[0].angular_diameter: must be in [0, 90], got 120"));
}

TEST_CASE("scene errors: film display and filter keys", "[scene][errors][filter]") {
    TempDir dir;
    auto with_film = [](const std::string& extra) {
        return scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6, )" + extra + " }");
    };
    const auto ok = load_scene(dir.write("ok.json", with_film(R"("exposure": -1.5, "tone_curve": "aces", "filter": { "type": "gaussian", "sigma": 0.4 })")));
    CHECK(ok.film.exposure == -1.5f);
    CHECK(ok.film.tone_curve == sweeptrace::ToneCurve::Aces);
    CHECK(ok.film.filter.type == sweeptrace::FilterSpec::Type::Gaussian);
    CHECK(ok.film.filter.radius == 1.5f);
    CHECK_THAT(load_error(dir, with_film(R"("tone_curve": "filmic")")),
               Catch::Contains("film.tone_curve: unknown tone curve \"filmic\" (known: clamp, aces)"));
    CHECK_THAT(load_error(dir, with_film(R"("exposure": 100)")), Catch::Contains("film.exposure: must be in [-64, 64]"));
    CHECK_THAT(load_error(dir, with_film(R"("filter": "tent")")), Catch::Contains("film.filter: must be an object"));
    CHECK_THAT(load_error(dir, with_film(R"("filter": { "type": "lanczos" })")),
               Catch::Contains("film.filter.type: unknown filter type \"lanczos\""));
    CHECK_THAT(load_error(dir, with_film(R"("filter": { "type": "tent", "radius": 0 })")),
               Catch::Contains("film.filter.radius: must be in [0.05, 16] pixels, got 0"));
    CHECK_THAT(load_error(dir, with_film(R"("filter": { "type": "box", "sigma": 1 })")),
               Catch::Contains("film.filter.sigma"));
    CHECK_THAT(load_error(dir, with_film(R"("filter": { "type": "mitchell", "b": 2 })")),
               Catch::Contains("film.filter.b: must be in [0, 1], got 2"));
}

TEST_CASE("scene errors: environment backgrounds", "[scene][errors][environment]") {
    TempDir dir;
    auto with_bg = [](const std::string& bg) {
        return scene_text(kSphere, kMaterials, R"({ "width": 8, "height": 6 })",
                          R"({ "position": [0, 0, 5], "look_at": [0, 0, 0] })", "  \"background\": " + bg + ",\n");
    };
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "nope.hdr" } })")),
               Catch::Contains("background.environment.file: environment image \"nope.hdr\" not found"));
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "x.hdr" }, "color": [0, 0, 0] })")),
               Catch::Contains("background: give exactly one of \"color\", \"sky\" or \"environment\""));
    dir.write("bad.hdr", "not an image");
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "bad.hdr" } })")),
               Catch::Contains("background.environment.file: cannot read") && Catch::Contains("not a Radiance HDR file"));
    // Every 8-bit sRGB format, whatever the case of its extension (refused by name, before reading).
    for (const char* name : {"photo.png", "photo.JPG", "photo.jpeg", "photo.tga", "photo.TGA"}) {
        dir.write(name, "x");
        CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": ")" + std::string(name) + R"(" } })")),
                   Catch::Contains("background.environment.file: an environment must be linear radiance") &&
                       Catch::Contains(std::filesystem::path(name).extension().string()));
    }
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
    for (int i = 0; i < 2; ++i) hdr += std::string{char(128), char(128), char(128), char(129)};
    dir.write("ok.hdr", hdr);
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "ok.hdr", "scale": -1 } })")),
               Catch::Contains("background.environment.scale: must be >= 0, got -1"));
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "ok.hdr", "turn": 3 } })")),
               Catch::Contains("background.environment.turn"));
    // ok.hdr is 2 x 1: an equirect map, not pbrt's square equal-area one.
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "ok.hdr", "mapping": "equal-area" } })")),
               Catch::Contains("background.environment.file: an equal-area map must be square, got 2x1"));
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "ok.hdr", "mapping": "octahedral" } })")),
               Catch::Contains("background.environment.mapping: unknown mapping \"octahedral\" (known: equirect, equal-area)"));
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "ok.hdr", "mapping": 2 } })")),
               Catch::Contains("background.environment.mapping: must be a string"));
    CHECK_THAT(load_error(dir, with_bg(R"({ "environment": { "file": "ok.hdr", "mirror": "yes" } })")),
               Catch::Contains("background.environment.mirror: must be true or false"));
}

TEST_CASE("scene errors: textures", "[scene][errors][texture]") {
    TempDir dir;
    auto with_albedo = [](const std::string& albedo) {
        return scene_text(kSphere, R"({ "m": { "type": "diffuse", "albedo": )" + albedo + " } }");
    };
    CHECK_THAT(load_error(dir, with_albedo(R"({ "checker": { "scale": 0 } })")),
               Catch::Contains("materials.m.albedo.checker.scale: must be > 0, got 0"));
    CHECK_THAT(load_error(dir, with_albedo(R"({ "checker": { "a": [2, 0, 0] } })")),
               Catch::Contains("materials.m.albedo.checker.a[0]: must be in [0, 1], got 2"));
    CHECK_THAT(load_error(dir, with_albedo(R"({ "image": { "file": "none.png" } })")),
               Catch::Contains("materials.m.albedo.image.file: texture image \"none.png\" not found"));
    CHECK_THAT(load_error(dir, with_albedo(R"({ "marble": {} })")), Catch::Contains("materials.m.albedo.marble"));
    CHECK_THAT(load_error(dir, with_albedo(R"({ "checker": {}, "image": { "file": "x.png" } })")),
               Catch::Contains("materials.m.albedo: give exactly one of \"checker\" or \"image\""));
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
    for (int i = 0; i < 2; ++i) hdr += std::string{char(128), char(128), char(128), char(130)};  // 2.0
    dir.write("bright.hdr", hdr);
    CHECK_THAT(load_error(dir, with_albedo(R"({ "image": { "file": "bright.hdr" } })")),
               Catch::Contains("materials.m.albedo.image.file: an albedo texture's values must lie in [0, 1]"));
    dir.write("ok.hdr", hdr.substr(0, hdr.size() - 8) + std::string{char(128), char(128), char(128), char(128)} +
                            std::string{char(128), char(128), char(128), char(128)});
    CHECK_THAT(load_error(dir, with_albedo(R"({ "image": { "file": "ok.hdr", "wrap": "tile" } })")),
               Catch::Contains("materials.m.albedo.image.wrap: unknown wrap mode \"tile\" (known: repeat, clamp, mirror)"));
}

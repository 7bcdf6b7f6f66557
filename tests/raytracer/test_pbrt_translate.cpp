// What the pbrt importer writes for each supported shape, material, texture, light and film
// setting (the JSON `sweeptrace convert` shows), and its warnings: one per kind, naming
// file:line and what was done instead, errors under --strict.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "convergence_harness.hpp"
#include "pbrt_test_support.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/render/lights/environment_light.hpp"
#include "raytracer/scene/scene_transform.hpp"

using namespace sweeptrace;
using sweeptrace::test::convert_text;
using sweeptrace::test::has_warning;
using sweeptrace::test::kFlipped;
using sweeptrace::test::TempDir;
using sweeptrace::test::world_with;
using nlohmann::json;

namespace {

json material_of(const TempDir& dir, const std::string& material) {
    const auto c = convert_text(dir, std::string(kFlipped) + "WorldBegin\n" + material + "\nShape \"sphere\"\n");
    const std::string name = c.doc["objects"][0]["material"];
    return c.doc["materials"][name];
}

json rgb(double r, double g, double b) { return json::array({r, g, b}); }

}  // namespace

TEST_CASE("pbrt materials: diffuse, dielectric, thindielectric, coateddiffuse, interface", "[pbrt]") {
    const TempDir dir;
    CHECK(material_of(dir, "Material \"diffuse\" \"rgb reflectance\" [0.1 0.2 0.3]") == json({{"type", "diffuse"}, {"albedo", rgb(0.1, 0.2, 0.3)}}));
    CHECK(material_of(dir, "Material \"diffuse\"") == json({{"type", "diffuse"}, {"albedo", rgb(0.5, 0.5, 0.5)}}));
    CHECK(material_of(dir, "Material \"dielectric\" \"float eta\" 1.33") == json({{"type", "dielectric"}, {"ior", 1.33}}));
    CHECK(material_of(dir, "Material \"thindielectric\"") == json({{"type", "thin_dielectric"}, {"ior", 1.5}}));
    // Rough: pbrt's alpha = sqrt(roughness) (remapped), ours alpha = r^2: r = roughness^(1/4).
    const json rough = material_of(dir, "Material \"dielectric\" \"float roughness\" 0.0625");
    CHECK(rough["type"] == "rough_dielectric");
    CHECK(rough["roughness"].get<double>() == Approx(0.5));
    const json raw = material_of(dir, "Material \"dielectric\" \"float roughness\" 0.0625 \"bool remaproughness\" false");
    CHECK(raw["roughness"].get<double>() == Approx(0.25));  // alpha = 0.0625 itself
    const json coated = material_of(dir, "Material \"coateddiffuse\" \"rgb reflectance\" [0.4 0.5 0.6] \"float roughness\" 0");
    CHECK(coated == json({{"type", "coated_diffuse"}, {"albedo", rgb(0.4, 0.5, 0.6)}, {"ior", 1.5}, {"roughness", 0.0}}));
    // An interface marks a medium boundary: the shape is left out.
    const auto c = convert_text(dir, std::string(kFlipped) + "WorldBegin\nMaterial \"interface\"\nShape \"sphere\"\n");
    CHECK(c.doc["objects"].empty());
    CHECK(c.warnings.empty());
}

TEST_CASE("pbrt materials: conductor as a named metal, as eta/k rgb, from reflectance", "[pbrt]") {
    const TempDir dir;
    CHECK(material_of(dir, "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\" \"float roughness\" 0") ==
          json({{"type", "conductor"}, {"metal", "Au"}, {"roughness", 0.0}}));
    CHECK(material_of(dir, "Material \"conductor\"")["metal"] == "Cu");  // pbrt-v4's default
    // Every metal pbrt-v4 names is one of ours, brass (CuZn) included: by name, with no warning.
    for (const char* m : {"Ag", "Al", "Au", "Cu", "CuZn", "MgO", "TiO2"}) {
        INFO(m);
        const std::string s = std::string("Material \"conductor\" \"spectrum eta\" \"metal-") + m + "-eta\" \"spectrum k\" \"metal-" + m + "-k\"";
        const auto c = convert_text(dir, std::string(kFlipped) + "WorldBegin\n" + s + "\nShape \"sphere\"\n");
        CHECK(c.doc["materials"][c.doc["objects"][0]["material"].get<std::string>()] == json({{"type", "conductor"}, {"metal", m}, {"roughness", 0.0}}));
        CHECK(c.warnings.empty());
    }
    const json rgbk = material_of(dir, "Material \"conductor\" \"rgb eta\" [0.2 0.9 1.1] \"rgb k\" [3.9 2.4 2.2] \"float roughness\" 0.01");
    CHECK(rgbk["eta"] == rgb(0.2, 0.9, 1.1));
    CHECK(rgbk["k"] == rgb(3.9, 2.4, 2.2));
    CHECK(rgbk["roughness"].get<double>() == Approx(std::pow(0.01, 0.25)));
    // reflectance r: eta 1, k = 2 sqrt(r) / sqrt(1 - r), whose normal-incidence Fresnel is r.
    const json refl = material_of(dir, "Material \"conductor\" \"rgb reflectance\" [0.5 0.5 0.5]");
    CHECK(refl["eta"] == rgb(1, 1, 1));
    const double k = refl["k"][0].get<double>();
    CHECK(k == Approx(2.0 * std::sqrt(0.5) / std::sqrt(0.5)));
    CHECK(((1 - 1) * (1 - 1) + k * k) / ((1 + 1) * (1 + 1) + k * k) == Approx(0.5));
}

TEST_CASE("pbrt materials: anisotropic roughness and mix are approximated with a warning", "[pbrt]") {
    const TempDir dir;
    const auto c = convert_text(dir, std::string(kFlipped) +
                                         "WorldBegin\nMaterial \"conductor\" \"float uroughness\" 0.01 \"float vroughness\" 0.04 \"bool remaproughness\" false\n"
                                         "Shape \"sphere\"\n");
    const json m = c.doc["materials"][c.doc["objects"][0]["material"].get<std::string>()];
    CHECK(m["roughness"].get<double>() == Approx(std::sqrt(std::sqrt(0.01 * 0.04))));
    CHECK(has_warning(c.warnings, "scene.pbrt:3: material \"conductor\": uroughness != vroughness"));
    const auto mix = convert_text(dir, world_with("MakeNamedMaterial \"a\" \"string type\" \"dielectric\"\n"
                                                  "MakeNamedMaterial \"m\" \"string type\" \"mix\" \"string materials\" [\"white\" \"a\"] \"float amount\" 0.8\n"
                                                  "NamedMaterial \"m\"\nShape \"sphere\""));
    CHECK(mix.doc["materials"]["m"]["type"] == "dielectric");
    CHECK(has_warning(mix.warnings, "a mix is approximated by the material of the larger weight (\"a\")"));
}

TEST_CASE("pbrt textures: imagemap, checkerboard, scale, constant", "[pbrt]") {
    const TempDir dir;
    dir.write("wood.png", "not read by the converter");
    const auto c = convert_text(dir, std::string(kFlipped) +
                                         "WorldBegin\nTexture \"w\" \"spectrum\" \"imagemap\" \"string filename\" \"wood.png\" \"string wrap\" \"clamp\"\n"
                                         "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" 4 \"float vscale\" 4 \"rgb tex1\" [1 0 0] \"rgb tex2\" [0 0 1]\n"
                                         "Texture \"half\" \"spectrum\" \"scale\" \"texture tex\" \"c\" \"float scale\" 0.5\n"
                                         "Texture \"k\" \"float\" \"constant\" \"float value\" 0.0625\n"
                                         "Material \"diffuse\" \"texture reflectance\" \"w\"\nShape \"sphere\"\n"
                                         "Material \"diffuse\" \"texture reflectance\" \"half\"\nShape \"sphere\"\n"
                                         "Material \"dielectric\" \"texture roughness\" \"k\"\nShape \"sphere\"\n");
    auto mat = [&](int i) { return c.doc["materials"][c.doc["objects"][i]["material"].get<std::string>()]; };
    CHECK(mat(0)["albedo"] == json({{"image", {{"file", "wood.png"}, {"wrap", "clamp"}}}}));
    CHECK(mat(1)["albedo"] == json({{"checker", {{"a", rgb(0.5, 0, 0)}, {"b", rgb(0, 0, 0.5)}, {"scale", 4.0}}}}));
    CHECK(mat(2)["roughness"].get<double>() == Approx(0.5));
    CHECK(c.warnings.empty());
}

TEST_CASE("pbrt shapes: sphere, disk, cylinder, trianglemesh, bilinearmesh, plymesh", "[pbrt]") {
    const TempDir dir;
    dir.write("m.ply", "ply\n");
    const auto c = convert_text(dir, std::string(kFlipped) +
                                         "WorldBegin\nShape \"sphere\" \"float radius\" 2\n"
                                         "Shape \"disk\" \"float radius\" 3 \"float height\" 1\n"
                                         "Shape \"cylinder\" \"float radius\" 0.5 \"float zmin\" 0 \"float zmax\" 4\n"
                                         "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n"
                                         "Shape \"bilinearmesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 0]\n"
                                         "Translate 0 0 7\nShape \"plymesh\" \"string filename\" \"m.ply\"\n");
    const json& o = c.doc["objects"];
    REQUIRE(o.size() == 6);
    CHECK(o[0]["type"] == "sphere");
    CHECK(o[0]["radius"] == 2.0);
    CHECK(o[1] == json({{"type", "disk"}, {"center", {0.0, 0.0, 1.0}}, {"normal", {0.0, 0.0, 1.0}}, {"radius", 3.0}, {"material", o[1]["material"]}}));
    CHECK(o[2]["type"] == "cylinder");
    CHECK(o[2]["height"] == 4.0);
    CHECK(o[2]["center"] == json({0.0, 2.0, 0.0}));
    CHECK(o[2]["transform"][0]["rotate"]["degrees"].get<double>() == Approx(90.0));
    // Inline meshes: the world's vertices and pbrt's indices.
    CHECK(o[3] == json({{"type", "mesh"}, {"vertices", {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0}}, {"indices", {0, 1, 2}}, {"material", o[3]["material"]}}));
    // The patch p00 p10 p01 p11 as (p00 p10 p11), (p00 p11 p01).
    CHECK(o[4]["indices"] == json({0, 1, 3, 0, 3, 2}));
    CHECK(o[5] == json({{"type", "mesh"}, {"file", "m.ply"}, {"material", o[5]["material"]}, {"transform", {{{"translate", {0.0, 0.0, 7.0}}}}}}));
    CHECK(has_warning(c.warnings, "scene.pbrt:5: Shape \"cylinder\": pbrt's cylinder is open"));
}

TEST_CASE("pbrt shapes: a plymesh under a mirroring transform is written mirrored, with no warning", "[pbrt]") {
    const TempDir dir;
    dir.write("m.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const std::string text = "WorldBegin\nMaterial \"diffuse\"\nTranslate 1 2 3\nRotate 30 0 1 0\nScale -2 1 1\nShape \"plymesh\" \"string filename\" \"m.ply\"\n";
    const auto c = convert_text(dir, text);
    CHECK(c.warnings.empty());
    const json& steps = c.doc["objects"][0]["transform"];
    CHECK(steps[0] == json({{"scale", {-1.0, 1.0, 1.0}}}));
    // The object's matrix, as our loader builds it, is pbrt's CTM.
    std::vector<std::string> warnings;
    const Scene s = load_pbrt_scene(dir.write("scene.pbrt", text), false, warnings);
    const glm::dmat4 ctm = translation_matrix({1, 2, 3}) * rotation_matrix({0, 1, 0}, 30.0) * scale_matrix({-2, 1, 1});
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 3; ++row) CHECK(s.objects[0].transform.to_world[col][row] == Approx(ctm[col][row]).margin(1e-6));
}

TEST_CASE("pbrt shapes: the emitting side of triangles follows ReverseOrientation and mirroring transforms", "[pbrt]") {
    const TempDir dir;
    auto front_z = [&](const std::string& prefix, const std::string& attrs) {
        const auto c = convert_text(dir, prefix + "WorldBegin\nAreaLightSource \"diffuse\"\n" + attrs +
                                             "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n");
        const json& t = c.doc["objects"][0];
        auto v = [&](int corner) {
            const int i = t["indices"][corner].get<int>();
            return glm::dvec3(t["vertices"][3 * i], t["vertices"][3 * i + 1], t["vertices"][3 * i + 2]);
        };
        return glm::cross(v(1) - v(0), v(2) - v(0)).z;  // pbrt's normal: +z for this order
    };
    CHECK(front_z(kFlipped, "") > 0.0);
    CHECK(front_z(kFlipped, "ReverseOrientation\n") < 0.0);
    // A transform that swaps handedness turns pbrt's normal over (the plane z = 0 itself is kept).
    CHECK(front_z(kFlipped, "Scale 1 1 -1\n") < 0.0);
    // The camera's handedness is the camera's: the world, and each side, stay pbrt's.
    CHECK(front_z("", "") > 0.0);
    CHECK(front_z("", "ReverseOrientation\n") < 0.0);
    // Mirrored in x the triangle's world winding turns, and pbrt's flip for a handedness swap
    // turns it back: the object's own +z, as the inverse transpose carries it.
    CHECK(front_z("", "Scale -1 1 1\n") > 0.0);
}

TEST_CASE("pbrt lights: area, point, spot, distant, infinite", "[pbrt]") {
    const TempDir dir;
    const auto c = convert_text(dir, std::string(kFlipped) +
                                         "WorldBegin\n"
                                         "LightSource \"point\" \"rgb I\" [1 2 3] \"float scale\" 2 \"point3 from\" [1 2 3]\n"
                                         "LightSource \"spot\" \"point3 from\" [0 5 0] \"point3 to\" [0 0 0] \"float coneangle\" 40 \"float conedeltaangle\" 10\n"
                                         "LightSource \"distant\" \"point3 from\" [0 1 0] \"point3 to\" [0 0 0] \"rgb L\" [3 3 3]\n"
                                         "LightSource \"infinite\" \"rgb L\" [0.1 0.2 0.3]\n"
                                         "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [4 5 6] \"float scale\" 0.5 \"bool twosided\" true\n"
                                         "Shape \"sphere\"\nAttributeEnd\n");
    const json& l = c.doc["lights"];
    REQUIRE(l.size() == 3);
    CHECK(l[0]["type"] == "point");
    CHECK(l[0]["intensity"] == rgb(2, 4, 6));
    CHECK(l[0]["position"] == rgb(1, 2, 3));
    CHECK(l[1]["type"] == "spot");
    CHECK(l[1]["direction"] == rgb(0, -5, 0));
    CHECK(l[1]["cone_angle"] == 40.0);
    CHECK(l[1]["falloff_start"] == 30.0);
    CHECK(l[1]["intensity"] == rgb(1, 1, 1));
    CHECK(l[2] == json({{"type", "directional"}, {"direction", rgb(0, -1, 0)}, {"irradiance", rgb(3, 3, 3)}, {"name", l[2]["name"]}}));
    CHECK(c.doc["background"] == json({{"color", rgb(0.1, 0.2, 0.3)}}));
    const json m = c.doc["materials"][c.doc["objects"][0]["material"].get<std::string>()];
    CHECK(m["emission"] == rgb(2, 2.5, 3));
    CHECK(m["two_sided"] == true);
    CHECK(m["albedo"] == rgb(0.5, 0.5, 0.5));  // an area light keeps its surface's material
    // power: radiance so that the one-sided disk of area pi emits 10 W: L 10 / (pi * pi).
    const auto p = convert_text(dir, std::string(kFlipped) + "WorldBegin\nAreaLightSource \"diffuse\" \"float power\" 10\nShape \"disk\"\n");
    const json pm = p.doc["materials"][p.doc["objects"][0]["material"].get<std::string>()];
    CHECK(pm["emission"][0].get<double>() == Approx(10.0 / (M_PI * M_PI)));
}

TEST_CASE("pbrt diffusetransmission: a blind lit from behind glows T E / pi toward the room", "[pbrt][render]") {
    // A plane z = 0 filling the view, seen from z = 5, lit from behind (z < 0) at normal incidence
    // by a distant light of irradiance E = 2; reflectance 0, so all its light is transmitted
    // diffusely: radiance T E / pi toward the camera, exactly, in every sample (the light is a
    // delta, found by next event estimation; paths sampled through the plane escape to black).
    // With the transmission dropped (our diffuse alone) the plane was black.
    const TempDir dir;
    const std::string text =
        "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n"
        "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n"
        "LightSource \"distant\" \"point3 from\" [0 0 -1] \"point3 to\" [0 0 0] \"rgb L\" [2 2 2]\n"
        "Material \"diffusetransmission\" \"rgb reflectance\" [0 0 0] \"rgb transmittance\" [0.5 0.4 0.3]\n"
        "Shape \"trianglemesh\" \"point3 P\" [-10 -10 0  10 -10 0  10 10 0  -10 10 0] \"integer indices\" [0 1 2  0 2 3]\n";
    std::vector<std::string> warnings;
    const Scene s = load_pbrt_scene(dir.write("blind.pbrt", text), false, warnings);
    CHECK(warnings.empty());
    const RenderResult r = testing::render_with(s, AccelKind::Bvh, 4, 3, 1);
    const glm::vec3 expected = glm::vec3(0.5f, 0.4f, 0.3f) * (2.0f / static_cast<float>(M_PI));
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) CHECK(r.image.at(x, y)[c] == Approx(expected[c]).epsilon(1e-4));
}

TEST_CASE("pbrt film, sampler, integrator and pixel filter", "[pbrt]") {
    const TempDir dir;
    const auto c = convert_text(dir, "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" 48 \"string filename\" \"out.exr\"\n"
                                     "Sampler \"independent\" \"integer pixelsamples\" 8\nIntegrator \"path\" \"integer maxdepth\" 3\n"
                                     "PixelFilter \"triangle\" \"float xradius\" 1.5 \"float yradius\" 1.5\nWorldBegin\n");
    const json& f = c.doc["film"];
    CHECK(f["width"] == 64);
    CHECK(f["height"] == 48);
    CHECK(f["spp"] == 8);
    CHECK(f["sampler"] == "independent");
    CHECK(f["max_depth"] == 4);  // pbrt's maxdepth counts bounces, ours vertices after the camera
    CHECK(f["filter"] == json({{"type", "tent"}, {"radius", 1.5}}));
    // pbrt-v4's defaults: 1280x720, 16 spp, maxdepth 5, a Gaussian filter of radius 1.5.
    const auto d = convert_text(dir, "WorldBegin\n");
    CHECK(d.doc["film"] == json({{"width", 1280}, {"height", 720}, {"spp", 16}, {"max_depth", 6},
                                 {"filter", {{"type", "gaussian"}, {"radius", 1.5}, {"sigma", 0.5}}}}));
    CHECK(d.doc["camera"]["fov"].get<double>() == Approx(90.0));  // 720 < 1280: fov spans y
    const auto mit = convert_text(dir, "PixelFilter \"mitchell\" \"float B\" 0 \"float C\" 0.5\nWorldBegin\n");
    CHECK(mit.doc["film"]["filter"] == json({{"type", "mitchell"}, {"radius", 2.0}, {"b", 0.0}, {"c", 0.5}}));
    const auto box = convert_text(dir, "PixelFilter \"box\"\nWorldBegin\n");
    CHECK(box.doc["film"]["filter"] == json({{"type", "box"}, {"radius", 0.5}}));
}

TEST_CASE("pbrt warnings: one per kind, naming the first place, --strict makes them errors", "[pbrt]") {
    const TempDir dir;
    const std::string text = world_with("Shape \"curve\" \"point3 P\" [0 0 0 1 1 1 2 2 2 3 3 3]\nShape \"curve\"\n"
                                        "Shape \"sphere\" \"float zmax\" 0.5 \"float frobs\" 2\nMakeNamedMedium \"fog\" \"string type\" \"cloud\"");
    const auto c = convert_text(dir, text);
    REQUIRE(c.warnings.size() == 4);
    CHECK(c.warnings[0] == "" + (dir.path() / "scene.pbrt").string() + ":4: Shape \"curve\" is not supported (ignored) (and 1 more like it)");
    CHECK(has_warning(c.warnings, ":6: Shape \"sphere\": a partial shape"));
    CHECK(has_warning(c.warnings, ":6: Shape \"sphere\": parameter \"float frobs\" is not supported (ignored)"));
    CHECK(has_warning(c.warnings, ":7: MakeNamedMedium \"fog\": medium type \"cloud\" is not supported"));
    try {
        convert_text(dir, text, true);
        FAIL("--strict accepted an unsupported shape");
    } catch (const InputError& e) {
        CHECK_THAT(std::string(e.what()), Catch::EndsWith("scene.pbrt:4: Shape \"curve\" is not supported (ignored) (--strict makes this an error)"));
    }
    // A scene using only supported features converts cleanly under --strict.
    CHECK(convert_text(dir, world_with("Shape \"sphere\""), true).warnings.empty());
}

TEST_CASE("pbrt scenes shaped like Bitterli's exports: a Transform camera that flips x, converted without a warning", "[pbrt]") {
    const TempDir dir;
    // The header of the "veach-mis" scene (Bitterli's rendering resources, pbrt-v4 version): the
    // camera matrix has determinant -1, so the world is taken as it is.
    const auto c = convert_text(dir, "Integrator \"path\" \"integer maxdepth\" [ 3 ]\n"
                                     "Transform [ 4.37113e-8 -0 -1 -0 -0 1 -0 -0 -1 -0 -4.37113e-8 -0 -0 -3.5 28.2792 1 ]\n"
                                     "Sampler \"sobol\" \"integer pixelsamples\" 64\n"
                                     "PixelFilter \"triangle\" \"float xradius\" [ 1 ] \"float yradius\" [ 1 ]\n"
                                     "Film \"rgb\" \"string filename\" [ \"veach-mis.png\" ] \"integer yresolution\" [ 720 ] \"integer xresolution\" [ 1280 ]\n"
                                     "Camera \"perspective\" \"float fov\" [ 20.114292 ]\nWorldBegin\n"
                                     "MakeNamedMaterial \"Smooth\" \"string type\" [ \"conductor\" ] \"float roughness\" [ 0.01 ]\n"
                                     "    \"bool remaproughness\" [ false ] \"rgb eta\" [ 0.2 0.92 1.1 ] \"rgb k\" [ 3.91 2.45 2.14 ]\n"
                                     "NamedMaterial \"Smooth\"\n"
                                     "Shape \"trianglemesh\" \"point3 P\" [ -1 0 -1 1 0 -1 1 0 1 -1 0 1 ] \"integer indices\" [ 0 1 2 0 2 3 ]\n"
                                     "    \"normal N\" [ 0 1 0 0 1 0 0 1 0 0 1 0 ] \"point2 uv\" [ 0 0 1 0 1 1 0 1 ]\n");
    CHECK(c.warnings.empty());
    const json& cam = c.doc["camera"];
    CHECK(cam["position"][0].get<double>() == Approx(28.2792));
    CHECK(cam["position"][1].get<double>() == Approx(3.5));
    CHECK(cam["position"][2].get<double>() == Approx(0.0).margin(1e-5));  // 4.37e-8 x 28.28 of the matrix
    const glm::dvec3 dir_(cam["look_at"][0].get<double>() - cam["position"][0].get<double>(),
                          cam["look_at"][1].get<double>() - cam["position"][1].get<double>(),
                          cam["look_at"][2].get<double>() - cam["position"][2].get<double>());
    CHECK(glm::normalize(dir_).x == Approx(-1.0));
    CHECK(c.doc["film"]["max_depth"] == 4);
    CHECK(c.doc["materials"]["Smooth"]["roughness"].get<double>() == Approx(0.1));
}

TEST_CASE("pbrt infinite light from a 2:1 map: pbrt-v3's z-up mapping as our rotate about +y", "[pbrt]") {
    const TempDir dir;
    Image sky(8, 4);
    for (auto& p : sky.pixels) p = glm::vec3(0.5f, 0.6f, 0.7f);
    write_image(sky, dir.path() / "sky.pfm");
    const std::string light = "WorldBegin\nAttributeBegin\nRotate -90 1 0 0\nLightSource \"infinite\" \"string filename\" \"sky.pfm\" \"float scale\" 2\nAttributeEnd\n";
    // pbrt-v3's equirect map is the mirror image of ours: our "mirror" and a turn about +y, whichever
    // way the camera is handed (the camera does not move the world).
    for (const std::string prefix : {"", kFlipped}) {
        const auto c = convert_text(dir, prefix + light);
        CHECK(c.warnings.empty());
        const json& env = c.doc["background"]["environment"];
        CHECK(env["file"] == "sky.pfm");
        CHECK(env["scale"] == 2.0);
        CHECK(env["mirror"] == true);
        CHECK(env["rotate"].get<double>() == Approx(90.0));
    }
    // A light transform that tilts the map: the whole turn, as an axis and degrees.
    const auto t = convert_text(dir, "WorldBegin\nRotate 30 1 0 0\nLightSource \"infinite\" \"string filename\" \"sky.pfm\"\n");
    CHECK(t.warnings.empty());
    CHECK(t.doc["background"]["environment"]["rotate"].contains("axis"));
    // One that shears it is no rotation: the nearest turn about +y, said.
    const auto h = convert_text(dir, "WorldBegin\nConcatTransform [1 0 0 0  0.5 1 0 0  0 0 1 0  0 0 0 1]\n"
                                     "LightSource \"infinite\" \"string filename\" \"sky.pfm\"\n");
    CHECK(has_warning(h.warnings, "the light's transform shears the map"));
    // A square map is pbrt-v4's equal-area mapping: ours, turned to pbrt's frame.
    write_image(Image(4, 4), dir.path() / "square.pfm");
    const auto s = convert_text(dir, "WorldBegin\nLightSource \"infinite\" \"string filename\" \"square.pfm\"\n");
    const json& env = s.doc["background"]["environment"];
    CHECK(s.warnings.empty());
    CHECK(env["mapping"] == "equal-area");
    CHECK_FALSE(env.contains("mirror"));
}

TEST_CASE("pbrt infinite light: pbrt's light-space directions land where pbrt puts them, equal-area and equirect", "[pbrt][environment]") {
    // Maps black but for marked texels, whose light-space directions are worked out by hand from
    // pbrt's mappings; the light turned by `Rotate -90 1 0 0` (light z -> world y, light y -> world -z),
    // then turned about the world's y by 30 degrees, as scenes do to aim the sun.
    // The same checks in a z-up world (no turn to y; the sun aimed about z) and under a light
    // transform that mirrors.
    const TempDir dir;
    glm::dmat4 mirror_y(1.0);
    mirror_y[1][1] = -1.0;
    const std::pair<std::string, glm::dmat4> turns[] = {
        {"Rotate 30 0 1 0\nRotate -90 1 0 0\n", rotation_matrix({0, 1, 0}, 30.0) * rotation_matrix({1, 0, 0}, -90.0)},
        {"Rotate 40 0 0 1\n", rotation_matrix({0, 0, 1}, 40.0)},
        {"Scale 1 -1 1\nRotate 20 0 0 1\n", mirror_y * rotation_matrix({0, 0, 1}, 20.0)}};
    for (const auto& [turn, to_world] : turns) {
    INFO(turn);
    auto world_of = [&](const glm::dvec3& light_dir) { return glm::vec3(glm::normalize(glm::dvec3(to_world * glm::dvec4(light_dir, 0.0)))); };
    auto radiance_toward = [&](const std::string& file, const glm::vec3& dir_world) {
        std::vector<std::string> warnings;
        const Scene sc = load_pbrt_scene(dir.write("env.pbrt", "WorldBegin\n" + turn + "LightSource \"infinite\" \"string filename\" \"" + file + "\"\n"),
                                         false, warnings);
        CHECK(warnings.empty());
        return environment_radiance(sc.background, dir_world);
    };
    // Equal-area (pbrt-v4), 16 x 16: the centre is light +z, the right edge's middle light +x, the
    // bottom edge's middle (last row) light +y (Clarberg's map: u -> x, v -> y, centre the pole).
    Image ea(16, 16);
    ea.at(8, 8) = glm::vec3(1, 0, 0);
    ea.at(15, 8) = glm::vec3(0, 1, 0);
    ea.at(8, 15) = glm::vec3(0, 0, 1);
    write_image(ea, dir.path() / "ea.pfm");
    // (Each direction a little to the +x and +y side, so that u and v fall inside texel 8, not on an edge.)
    CHECK(radiance_toward("ea.pfm", world_of({0.01, 0.01, 1})) == glm::vec3(1, 0, 0));
    CHECK(radiance_toward("ea.pfm", world_of({1, 0.01, 0.01})) == glm::vec3(0, 1, 0));
    CHECK(radiance_toward("ea.pfm", world_of({0.01, 1, 0.01})) == glm::vec3(0, 0, 1));
    CHECK(radiance_toward("ea.pfm", world_of({0, 0, -1})) == glm::vec3(0, 0, 0));
    // Equirect (pbrt-v3), 16 x 8: u = phi / 2 pi (phi from light +x toward +y), v = theta / pi.
    Image er(16, 8);
    er.at(0, 4) = glm::vec3(1, 0, 0);   // phi ~ 0: light +x, just below the equator
    er.at(4, 4) = glm::vec3(0, 1, 0);   // phi ~ pi/2: light +y
    er.at(8, 0) = glm::vec3(0, 0, 1);   // theta ~ 0: near light +z
    write_image(er, dir.path() / "er.pfm");
    auto sph = [](double theta, double phi) { return glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)); };
    const double t4 = (4.5 / 8.0) * M_PI;  // row 4's centre
    CHECK(radiance_toward("er.pfm", world_of(sph(t4, (0.5 / 16.0) * 2.0 * M_PI))) == glm::vec3(1, 0, 0));
    CHECK(radiance_toward("er.pfm", world_of(sph(t4, (4.5 / 16.0) * 2.0 * M_PI))) == glm::vec3(0, 1, 0));
    CHECK(radiance_toward("er.pfm", world_of(sph((0.5 / 8.0) * M_PI, (8.5 / 16.0) * 2.0 * M_PI))) == glm::vec3(0, 0, 1));
    // The mirror matters: the texel left of +y (phi a little less than pi/2) is not what +y shows.
    CHECK(radiance_toward("er.pfm", world_of(sph(t4, (3.5 / 16.0) * 2.0 * M_PI))) == glm::vec3(0, 0, 0));
    }
}

TEST_CASE("pbrt-v3's infinite light \"mapname\" under Rotate and a z-up ConcatTransform reads its map, not a white sky", "[pbrt][environment]") {
    // A pbrt-v3 scene lit like Bitterli's classroom: the sky map named by "mapname" (pbrt-v4 says
    // "filename"), "L" multiplying it, under `Rotate 90 0 1 0` (aiming) and Tungsten's z-up-to-y-up
    // ConcatTransform. Read as pbrt's constant light, it was a white background (L's default 1),
    // bright where the map's lower half is black. Worked by hand: the CTM is Ry(90) * M, M taking
    // light x -> world -x, y -> -z, z -> +y; then Ry(90) takes -x -> +z, -z -> -x, +y -> +y, so
    // light (a, b, c) is world (-b, c, a): light +z is up.
    const TempDir dir;
    Image er(16, 8);  // pbrt-v3 equirect: u = phi / 2 pi from light +x toward +y, v = theta / pi from +z
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 16; ++x) er.at(x, y) = glm::vec3(0.25f, 0.5f, 1.0f);  // sky above, black below
    er.at(2, 3) = glm::vec3(1, 0, 0);  // phi in (2, 3) / 16 turns, theta in (3, 4) / 8 of pi: just above the horizon
    write_image(er, dir.path() / "sky.pfm");
    std::vector<std::string> warnings;
    const Scene sc = load_pbrt_scene(dir.write("v3.pbrt", "WorldBegin\nAttributeBegin\nRotate 90 0 1 0\n"
                                                          "ConcatTransform [ -1 0 0 0  0 0 -1 0  0 1 0 0  0 0 0 1 ]\n"
                                                          "LightSource \"infinite\" \"string mapname\" \"sky.pfm\" \"rgb L\" [2 2 2]\n"
                                                          "AttributeEnd\n"),
                                     false, warnings);
    CHECK(warnings.empty());
    REQUIRE(sc.background.kind == Background::Kind::Environment);
    const double theta = 3.5 / 8.0 * M_PI, phi = 2.5 / 16.0 * 2.0 * M_PI;
    const glm::dvec3 light(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    const glm::vec3 world(-light.y, light.z, light.x);
    CHECK(environment_radiance(sc.background, world) == glm::vec3(2, 0, 0));
    // Its neighbour one texel less in phi is sky, and straight down is the map's black lower half.
    const double phi0 = 1.5 / 16.0 * 2.0 * M_PI;
    const glm::vec3 beside(-std::sin(theta) * std::sin(phi0), std::cos(theta), std::sin(theta) * std::cos(phi0));
    CHECK(environment_radiance(sc.background, beside) == glm::vec3(0.5f, 1.0f, 2.0f));
    CHECK(environment_radiance(sc.background, glm::vec3(0.1f, -1.0f, 0.2f)) == glm::vec3(0.0f));
}

TEST_CASE("pbrt film: the sensor's imaging ratio (shutter time x iso / 100) multiplies every emitter", "[pbrt]") {
    const TempDir dir;
    write_image(Image(4, 2), dir.path() / "sky.pfm");
    auto convert = [&](const std::string& header, const std::string& env) {
        return convert_text(dir, header + "WorldBegin\n" + env +
                                     "LightSource \"point\" \"rgb I\" [1 2 3]\nLightSource \"distant\" \"rgb L\" [2 2 2]\n"
                                     "AreaLightSource \"diffuse\" \"rgb L\" [4 5 6]\nShape \"sphere\"\n");
    };
    const std::string constant = "LightSource \"infinite\" \"rgb L\" [0.1 0.2 0.3]\n";
    const auto plain = convert("", constant);
    const auto iso = convert("Film \"rgb\" \"float iso\" 400\n", constant);
    CHECK(iso.warnings.empty());
    const json& a = plain.doc;
    const json& b = iso.doc;
    CHECK(b["lights"][0]["intensity"] == rgb(4, 8, 12));
    CHECK(b["lights"][1]["irradiance"] == rgb(8, 8, 8));
    const std::string key = b["objects"][0]["material"];
    CHECK(b["materials"][key]["emission"] == rgb(16, 20, 24));
    CHECK(b["background"]["color"][2].get<double>() == Approx(4.0 * a["background"]["color"][2].get<double>()));
    // A shutter half as long at iso 200 is the plain scene; an environment map's scale carries it.
    const auto half = convert("Camera \"perspective\" \"float shutteropen\" 0 \"float shutterclose\" 0.5\nFilm \"rgb\" \"float iso\" 200\n", constant);
    CHECK(half.doc["lights"][0]["intensity"] == a["lights"][0]["intensity"]);
    CHECK(half.doc["lights"][1]["irradiance"] == a["lights"][1]["irradiance"]);
    const auto env = convert("Film \"rgb\" \"float iso\" 50\n", "LightSource \"infinite\" \"string filename\" \"sky.pfm\" \"float scale\" 3\n");
    CHECK(env.doc["background"]["environment"]["scale"].get<double>() == Approx(1.5));
    // Films of earlier pbrt versions: "scale" multiplies the pixels, "exposuretime" is the shutter's.
    const auto old = convert("Film \"rgb\" \"float scale\" 2 \"float exposuretime\" 0.25 \"float iso\" 400\n", constant);
    CHECK(old.warnings.empty());
    CHECK(old.doc["lights"][0]["intensity"] == rgb(2, 4, 6));
}

TEST_CASE("pbrt sampler: every pbrt-v4 sampler of the same image is our Sobol sampler, silently, an unjittered one is said", "[pbrt]") {
    const TempDir dir;
    for (const char* type : {"halton", "pmj02bn", "zsobol", "paddedsobol", "sobol"}) {
        const auto c = convert_text(dir, std::string("Sampler \"") + type + "\" \"integer pixelsamples\" 8\nWorldBegin\n");
        INFO(type);
        CHECK(c.warnings.empty());
        CHECK(c.doc["film"]["sampler"] == "sobol");
        CHECK(c.doc["film"]["spp"] == 8);
    }
    const auto st = convert_text(dir, "Sampler \"stratified\" \"integer xsamples\" 2 \"integer ysamples\" 3\nWorldBegin\n");
    CHECK(st.warnings.empty());
    CHECK(st.doc["film"]["spp"] == 6);
    const auto fixed = convert_text(dir, "Sampler \"stratified\" \"bool jitter\" false\nWorldBegin\n");
    CHECK(has_warning(fixed.warnings, "\"jitter\" false"));
    const auto other = convert_text(dir, "Sampler \"lowdiscrepancy\"\nWorldBegin\n");
    CHECK(has_warning(other.warnings, "is not a pbrt-v4 sampler"));
    CHECK(convert_text(dir, "Sampler \"independent\"\nWorldBegin\n").doc["film"]["sampler"] == "independent");
}

// Textures on every parameter (render/materials/texture.hpp, scene/load_texture.hpp): roughness, metal tint
// and emission maps render exactly the image of the constant they encode; a .png read as data
// keeps its stored codes (no sRGB decoding); wrap modes at chosen uvs; an image shared by every
// parameter that names it; light samples read an emission texture where they land (NEE+MIS
// agrees with BSDF-only sampling on a checker-emitting quad and mesh, both accels).
#include <catch2/catch.hpp>

#include <string>

#include "convergence_harness.hpp"
#include "raytracer/image/srgb.hpp"
#include "raytracer/render/materials/texture.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// A metal sphere (or any material `m`) on a diffuse floor under a sky: every sample's value
// depends on the material at each hit.
std::string sphere_scene(const std::string& material) {
    return R"({ "camera": { "position": [0, 1, 4], "look_at": [0, 0.5, 0] }, "film": { "width": 24, "height": 16, "spp": 4 },
        "background": { "sky": { "horizon": [1, 1, 1], "zenith": [0.3, 0.5, 1] } },
        "materials": { "m": )" + material + R"(, "floor": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5] } },
        "objects": [ { "type": "sphere", "center": [0, 0.7, 0], "radius": 0.7, "material": "m" },
                     { "type": "quad", "corner": [-4, 0, -4], "edge_u": [0, 0, 8], "edge_v": [8, 0, 0], "material": "floor" } ] })";
}

const Material& named(const Scene& s, const std::string& name) {
    for (const Material& m : s.materials)
        if (m.name == name) return m;
    FAIL("no material " << name);
    return s.materials[0];
}

void check_same_image(const Scene& a, const Scene& b) {
    for (AccelKind accel : {AccelKind::Bvh, AccelKind::Embree}) {
        const RenderResult ra = render_with(a, accel, 4, 5, 7), rb = render_with(b, accel, 4, 5, 7);
        REQUIRE(ra.image.pixels.size() == rb.image.pixels.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < ra.image.pixels.size(); ++i) differ += ra.image.pixels[i] != rb.image.pixels[i];
        INFO((accel == AccelKind::Bvh ? "bvh" : "embree") << ": " << differ << " pixels differ");
        CHECK(differ == 0);
    }
}

// A w x h image of one value, written as `name` in `dir` (a .png stores srgb_encode(value)).
void write_constant(const test::TempDir& dir, const std::string& name, const glm::vec3& value, int w = 3, int h = 2) {
    Image img(w, h);
    for (auto& p : img.pixels) p = value;
    write_image(img, dir.path() / name);
}

}  // namespace

TEST_CASE("texture params: roughness and tint maps render the image of the constants they encode", "[render][texture]") {
    test::TempDir dir;
    // 8-bit code 77 as data is roughness 77 / 255 (sRGB-decoded it would be 0.0742): the .png
    // stores code 77 when written from its decoded value.
    write_constant(dir, "rough.png", glm::vec3(srgb_decode(77.0f / 255.0f)));
    write_constant(dir, "rough.exr", glm::vec3(0.3f));
    write_constant(dir, "tint.png", glm::vec3(srgb_decode(200.0f / 255.0f), srgb_decode(150.0f / 255.0f), srgb_decode(90.0f / 255.0f)));
    const Scene constant = load_scene(dir.write("c.json", sphere_scene(R"({ "type": "metal", "roughness": 0.3019607843137255, "albedo": [1, 1, 1] })")));
    REQUIRE(named(constant, "m").roughness == 77.0f / 255.0f);
    const Scene png = load_scene(dir.write("p.json", sphere_scene(R"({ "type": "metal", "roughness": { "image": { "file": "rough.png" } }, "albedo": [1, 1, 1] })")));
    REQUIRE(named(png, "m").roughness_texture == 0);
    CHECK(png.textures[0].linear_data);
    CHECK(png.textures[0].image->pixels[0] == glm::vec3(77.0f / 255.0f));  // the stored code, not decoded
    check_same_image(constant, png);

    const Scene c03 = load_scene(dir.write("c3.json", sphere_scene(R"({ "type": "metal", "roughness": 0.3, "albedo": [0.7, 0.6, 0.5] })")));
    const Scene exr = load_scene(dir.write("e.json", sphere_scene(R"({ "type": "metal", "roughness": { "image": { "file": "rough.exr", "wrap": "mirror" } },
        "albedo": { "checker": { "a": [0.7, 0.6, 0.5], "b": [0.7, 0.6, 0.5] } } })")));
    check_same_image(c03, exr);

    // The metal's tint from a colour .png: decoded to linear, the constant is the decoded value.
    const Scene tinted = load_scene(dir.write("t.json", sphere_scene(R"({ "type": "metal", "roughness": 0.2, "albedo": { "image": { "file": "tint.png" } } })")));
    Scene tint_constant = tinted;
    Material& plain = tint_constant.materials[&named(tinted, "m") - tinted.materials.data()];
    plain.albedo_texture = -1;
    plain.albedo = glm::vec3(srgb_decode(200.0f / 255.0f), srgb_decode(150.0f / 255.0f), srgb_decode(90.0f / 255.0f));
    CHECK(tinted.textures[0].image->pixels[0] == plain.albedo);
    check_same_image(tint_constant, tinted);
}

namespace {

// A quad light over a diffuse floor; the light's emission from `emission` (JSON).
std::string lit_floor(const std::string& emission, const std::string& light_shape) {
    return R"({ "camera": { "position": [0, 3, 3], "look_at": [0, 0, 0] }, "film": { "width": 24, "height": 24, "spp": 4 },
        "materials": { "lamp": { "type": "emissive", "emission": )" + emission + R"( },
                       "floor": { "type": "diffuse", "albedo": [0.6, 0.6, 0.6] } },
        "objects": [ )" + light_shape + R"(,
                     { "type": "quad", "corner": [-3, 0, -3], "edge_u": [0, 0, 6], "edge_v": [6, 0, 0], "material": "floor" } ] })";
}

const char* kQuadLight = R"({ "type": "quad", "corner": [-0.5, 1, -0.5], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "material": "lamp" })";

}  // namespace

TEST_CASE("texture params: an emission map renders the image of the constant it encodes", "[render][texture][lights]") {
    test::TempDir dir;
    write_constant(dir, "glow.exr", glm::vec3(2.5f, 1.25f, 0.5f));
    const Scene constant = load_scene(dir.write("c.json", lit_floor("[2.5, 1.25, 0.5]", kQuadLight)));
    const Scene checker = load_scene(dir.write("k.json", lit_floor(R"({ "checker": { "a": [2.5, 1.25, 0.5], "b": [2.5, 1.25, 0.5] } })", kQuadLight)));
    const Scene image = load_scene(dir.write("i.json", lit_floor(R"({ "image": { "file": "glow.exr" } })", kQuadLight)));
    REQUIRE(named(image, "lamp").emission_texture == 0);
    CHECK(named(image, "lamp").emission == glm::vec3(2.5f, 1.25f, 0.5f));  // the mean: the light's selection weight
    check_same_image(constant, checker);
    check_same_image(constant, image);
}

TEST_CASE("texture params: light samples read the emission texture where they land (NEE+MIS = BSDF-only)", "[render][texture][lights]") {
    test::TempDir dir;
    dir.write("lamp.obj", "v -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                          "f 1/1 4/4 3/3\nf 1/1 3/3 2/2\n");  // facing down
    const std::string checker = R"({ "checker": { "a": [6, 6, 6], "b": [0, 0, 0], "scale": 2 } })";
    for (const char* shape : {kQuadLight, R"({ "type": "mesh", "file": "lamp.obj", "material": "lamp" })"}) {
        INFO(shape);
        const Scene scene = load_scene(dir.write("s.json", lit_floor(checker, shape)));
        for (AccelKind accel : {AccelKind::Bvh, AccelKind::Embree}) {
            const RenderResult mis = render_with(scene, accel, 64, 2, 21, Sampling::NeeMis);
            const RenderResult bsdf = render_with(scene, accel, 256, 2, 22, Sampling::BsdfOnly);
            Image variance(mis.image.width, mis.image.height);
            for (std::size_t i = 0; i < variance.pixels.size(); ++i)
                variance.pixels[i] = mis.variance.pixels[i] + bsdf.variance.pixels[i];
            BlockTestOptions options;
            options.block = 4;
            options.golden_is_8bit = false;
            const BlockTestResult t = block_test(mis.image, bsdf.image, variance, options);
            INFO(t.summary());
            CHECK(t.pass());
        }
    }
}

TEST_CASE("texture params: wrap modes at chosen uvs", "[render][texture]") {
    Texture t;
    t.kind = Texture::Kind::Image;
    auto img = std::make_shared<Image>(3, 1);
    img->at(0, 0) = glm::vec3(0.0f);
    img->at(1, 0) = glm::vec3(1.0f);
    img->at(2, 0) = glm::vec3(2.0f);
    t.image = img;
    // Texel i's centre is u = (i + 1/2) / 3; one row, so v does not matter. Centres of the
    // texels k = -3 .. 5 beyond the image read: repeat k mod 3, clamp the edge, mirror 2 1 0 | 0 1 2 | 2 1 0.
    const float repeat[] = {0, 1, 2, 0, 1, 2, 0, 1, 2}, clamp[] = {0, 0, 0, 0, 1, 2, 2, 2, 2},
                mirror[] = {2, 1, 0, 0, 1, 2, 2, 1, 0};
    for (int k = -3; k <= 5; ++k) {
        const glm::vec2 uv((static_cast<float>(k) + 0.5f) / 3.0f, 0.5f);
        INFO("texel " << k);
        t.wrap = Texture::Wrap::Repeat;
        CHECK(eval_texture(t, uv).x == repeat[k + 3]);
        t.wrap = Texture::Wrap::Clamp;
        CHECK(eval_texture(t, uv).x == clamp[k + 3]);
        t.wrap = Texture::Wrap::Mirror;
        CHECK(eval_texture(t, uv).x == mirror[k + 3]);
    }
    // Between the last texel and the one past the edge (u = 1): repeat blends texel 2 with
    // texel 0, mirror and clamp with texel 2 itself.
    t.wrap = Texture::Wrap::Repeat;
    CHECK(eval_texture(t, {1.0f, 0.5f}).x == 1.0f);
    t.wrap = Texture::Wrap::Mirror;
    CHECK(eval_texture(t, {1.0f, 0.5f}).x == 2.0f);
}

TEST_CASE("texture params: one image however many parameters and materials read it", "[scene][texture]") {
    test::TempDir dir;
    Image img(2, 1);
    img.at(0, 0) = glm::vec3(srgb_decode(10.0f / 255.0f), srgb_decode(128.0f / 255.0f), srgb_decode(255.0f / 255.0f));
    img.at(1, 0) = glm::vec3(srgb_decode(1.0f / 255.0f), srgb_decode(254.0f / 255.0f), 0.0f);
    write_image(img, dir.path() / "map.png");
    write_constant(dir, "lin.exr", glm::vec3(0.25f));
    const std::string other_spelling = "../" + dir.path().filename().string() + "/map.png";
    const Scene s = load_scene(dir.write("s.json", R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
        "film": { "width": 4, "height": 4 }, "objects": [],
        "materials": {
          "a": { "type": "metal", "albedo": { "image": { "file": "map.png" } }, "roughness": { "image": { "file": ")" + other_spelling + R"(" } },
                 "normal_map": { "image": { "file": "map.png" } } },
          "b": { "type": "diffuse", "albedo": { "image": { "file": "./map.png" } }, "normal_map": { "image": { "file": "map.png" } } },
          "c": { "type": "diffuse", "albedo": { "image": { "file": "lin.exr" } }, "normal_map": { "image": { "file": "lin.exr" } } } } })"));
    REQUIRE(s.textures.size() == 7);
    auto image = [&](int index) { return s.textures[static_cast<std::size_t>(index)].image; };
    const Material &a = named(s, "a"), &b = named(s, "b"), &c = named(s, "c");
    const auto colour = image(a.albedo_texture), data = image(a.roughness_texture);
    CHECK(colour != data);  // the two readings of one .png (read from disk once, converted)
    CHECK(image(a.normal_texture) == data);
    CHECK(image(b.albedo_texture) == colour);
    CHECK(image(b.normal_texture) == data);
    CHECK(image(c.albedo_texture) == image(c.normal_texture));  // linear: one reading
    CHECK(colour->pixels[0] == img.at(0, 0));
    CHECK(data->pixels[0] == glm::vec3(10.0f / 255.0f, 128.0f / 255.0f, 1.0f));
    CHECK(data->pixels[1] == glm::vec3(1.0f / 255.0f, 254.0f / 255.0f, 0.0f));
}

TEST_CASE("texture params: the same image at 1 and 3 threads with every textured parameter and OBJ materials", "[render][texture]") {
    test::TempDir dir;
    dir.write("sq.obj", "mtllib sq.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                        "usemtl dark\nf 1/1 2/2 3/3\nusemtl lamp\nf 1/1 3/3 4/4\n");
    dir.write("sq.mtl", "newmtl dark\nKd 0.2 0.3 0.4\nnorm n.png\nnewmtl lamp\nKd 0 0 0\nKe 3 3 3\n");
    Image n(2, 2);
    n.at(0, 0) = glm::vec3(srgb_decode(0.7f), srgb_decode(0.5f), srgb_decode(0.8f));
    n.at(1, 1) = glm::vec3(srgb_decode(0.4f), srgb_decode(0.6f), srgb_decode(0.9f));
    write_image(n, dir.path() / "n.png");
    const Scene scene = load_scene(dir.write("s.json", R"({ "camera": { "position": [0, 0.5, 4], "look_at": [0, 0, 0] },
        "film": { "width": 20, "height": 16 }, "background": { "sky": { "horizon": [1, 1, 1], "zenith": [0.2, 0.4, 1] } },
        "materials": { "ball": { "type": "metal", "albedo": { "checker": { "a": [0.9, 0.8, 0.7], "b": [0.5, 0.5, 0.5] } },
                                 "roughness": { "checker": { "a": 0.1, "b": 0.6, "scale": 5 } },
                                 "normal_map": { "image": { "file": "n.png", "wrap": "mirror" } },
                                 "bump_map": { "image": { "file": "n.png" } }, "bump_scale": 0.03,
                                 "emission": { "checker": { "a": [0, 0, 0], "b": [0.5, 0.2, 0.1], "scale": 3 } } } },
        "objects": [ { "type": "mesh", "file": "sq.obj", "transform": [{ "translate": [0, 0, -1] }] },
                     { "type": "sphere", "center": [0.3, 0, 0.5], "radius": 0.5, "material": "ball" } ] })"));
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
        const auto accel = make_accel(kind, scene);
        const auto [one, three] = render_on_1_and_3_threads(scene, *accel);
        CHECK(same_bits(one.image, three.image));
        CHECK(one.stats.nonfinite_samples == 0);
    }
}

// The experiments behind docs/reference-deviations.md: Bitterli's scenes (../shared/bitterli)
// rendered small through the pbrt importer and compared with TungstenRender.exr box-filtered to
// the same size, once as the pbrt-v4 file says and once with what the file lost in conversion put
// back. Each asserts the explanation (the change brings the compared region within a few percent
// of the reference, and without it the region is far off) and prints its figures.
// Hidden from the default suite ([.]: minutes of CPU); run them with
//   ./build/tests/raytracer_tests "[reference-deviations]" -s
// They say SKIPPED and pass without ../shared/bitterli.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raytracer/accel/accel.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/image/reference_compare.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"
#include "raytracer/scene/scene.hpp"

using namespace sweeptrace;

namespace {

std::filesystem::path bitterli(const std::string& scene) {
    return std::filesystem::path(SWEEPTRACE_SHARED_DIR) / "bitterli" / scene;
}

bool have(const std::string& scene) {
    if (std::filesystem::is_regular_file(bitterli(scene) / "scene-v4.pbrt")) return true;
    std::printf("SKIPPED: needs %s (the shared/ folder beside the checkout)\n", bitterli(scene).string().c_str());
    return false;
}

Scene load(const std::string& scene, int width) {
    std::vector<std::string> warnings;
    Scene s = load_pbrt_scene(bitterli(scene) / "scene-v4.pbrt", false, warnings);
    s.film.height = static_cast<int>(std::lround(static_cast<double>(s.film.height) * width / s.film.width));
    s.film.width = width;
    return s;
}

Material& material(Scene& s, const std::string& name) {
    for (Material& m : s.materials)
        if (m.name == name) return m;
    FAIL("no material " << name);
    throw;
}

std::uint32_t material_index(const Scene& s, const std::string& name) {
    for (std::uint32_t i = 0; i < s.materials.size(); ++i)
        if (s.materials[i].name == name) return i;
    FAIL("no material " << name);
    throw;
}

Image render_small(const Scene& s, int spp, int max_depth, Sampling sampling = Sampling::NeeMis) {
    const auto accel = make_accel(AccelKind::Bvh, s);
    RenderOptions o;
    o.sampling = sampling;
    o.spp = spp;
    o.max_depth = max_depth;
    o.seed = 7;
    o.sampler = s.film.sampler;
    return render(s, *accel, o).image;
}

// The reference box-filtered by an integer factor to `width` (a non-finite pixel counts as 0).
Image reference(const std::string& scene, int width, int height) {
    const Image full = read_image(bitterli(scene) / "TungstenRender.exr");
    const int k = full.width / width;
    Image out(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::dvec3 sum(0.0);
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) {
                    const glm::vec3 p = full.at(std::min(x * k + i, full.width - 1), std::min(y * k + j, full.height - 1));
                    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) sum += glm::dvec3(p);
                }
            out.at(x, y) = glm::vec3(sum / double(k * k));
        }
    return out;
}

// Per channel, sum(ours) / sum(reference) over the rectangle [x0, x1) x [y0, y1) in fractions of
// the image (the whole image by default).
glm::dvec3 ratio(const Image& ours, const Image& ref, double x0 = 0, double y0 = 0, double x1 = 1, double y1 = 1) {
    glm::dvec3 a(0.0), b(0.0);
    for (int y = int(y0 * ours.height); y < int(y1 * ours.height); ++y)
        for (int x = int(x0 * ours.width); x < int(x1 * ours.width); ++x) {
            a += glm::dvec3(ours.at(x, y));
            b += glm::dvec3(ref.at(x, y));
        }
    return a / b;
}

void print(const char* what, const glm::dvec3& r) { std::printf("  %-58s %.3f %.3f %.3f\n", what, r.x, r.y, r.z); }

bool within(const glm::dvec3& r, double tol) {
    return std::fabs(r.x - 1.0) <= tol && std::fabs(r.y - 1.0) <= tol && std::fabs(r.z - 1.0) <= tol;
}

// coffee's "Metal" as its Tungsten form has it (111116/toyray-scenes, coffee/scene.json, commit
// 9e68a8d8): "mirror", albedo 1, no Fresnel term, where the pbrt-v4 file has a silver conductor.
void coffee_tungsten_mirror(Scene& s) {
    Material& metal = material(s, "Metal");
    metal = Material{};
    metal.name = "Metal";
    metal.type = Material::Type::Metal;
    metal.roughness = 0.0f;
    metal.albedo = glm::vec3(1.0f);
}

// The regions of coffee the experiments judge (image fractions at 200 x 250): the silver handle
// left of the pot, and the bright band in the glass just above the pot's silver ring.
glm::dvec3 coffee_handle(const Image& im, const Image& ref) { return ratio(im, ref, 0.20, 0.36, 0.25, 0.80); }
glm::dvec3 coffee_band(const Image& im, const Image& ref) { return ratio(im, ref, 0.30, 0.72, 0.70, 0.76); }

}  // namespace

TEST_CASE("reference deviations: classroom's conductors lost Tungsten's albedo multipliers", "[.][reference-deviations]") {
    if (!have("classroom")) return;
    // Tungsten's form (tungsten-scene.json) gives ChairFrame albedo 0.75 and WindowFrame 0.47 on
    // top of the metal's Fresnel term; pbrt-v4's conductor has no such factor and the file dropped it.
    Scene s = load("classroom", 160);
    const Image ref = reference("classroom", s.film.width, s.film.height);
    const glm::dvec3 as_file = ratio(render_small(s, 64, s.film.max_depth), ref);
    material(s, "ChairFrame").albedo = glm::vec3(0.75f);
    material(s, "WindowFrame").albedo = glm::vec3(0.47f);
    const glm::dvec3 restored = ratio(render_small(s, 64, s.film.max_depth), ref);
    std::printf("classroom, 160 px, 64 spp: image mean / reference, r g b\n");
    print("as the pbrt-v4 file says", as_file);
    print("ChairFrame x 0.75, WindowFrame x 0.47 (Tungsten's albedos)", restored);
    CHECK(as_file.y > 1.1);
    CHECK(within(restored, 0.03));
}

TEST_CASE("reference deviations: veach-mis's plates lost an albedo of 0.3 and are Beckmann, and the reference is direct light", "[.][reference-deviations]") {
    if (!have("veach-mis")) return;
    // The plates' reflections of the lights, where a near-mirror shows the light's radiance times
    // the Fresnel term, are 3.3 times the reference's in every channel alike: the same copper
    // Fresnel colour scaled by 0.30, the kind of albedo multiplier classroom's conductors lost.
    // Our pbrt maxdepth 1 (direct light only) is --max-depth 2 here; the file's maxdepth 3 is 4.
    Scene s = load("veach-mis", 320);
    const Image ref = reference("veach-mis", s.film.width, s.film.height);
    // The top (smoothest, alpha 0.01) plate's reflection of the two larger lights, and the floor
    // in front of the plates (image fractions at 320 x 180).
    auto plate = [&](const Image& im) { return ratio(im, ref, 0.45, 0.42, 0.70, 0.45); };
    auto floor = [&](const Image& im) { return ratio(im, ref, 0.80, 0.92, 1.00, 1.00); };
    auto wall = [&](const Image& im) { return ratio(im, ref, 0.00, 0.05, 0.25, 0.35); };
    const Image as_file = render_small(s, 64, 2);
    for (const char* m : {"Smooth", "Glossy", "Rough", "SuperRough"}) material(s, m).albedo = glm::vec3(0.3f);
    const Image direct = render_small(s, 64, 2);
    const Image depth3 = render_small(s, 64, 3);
    const Image full = render_small(s, 64, 4);
    std::printf("veach-mis, 320 px, 64 spp: ours / reference, r g b\n");
    print("top plate's highlights, plates as the file says, direct", plate(as_file));
    print("top plate's highlights, plates x 0.3, direct", plate(direct));
    print("image mean, plates as the file says, direct", ratio(as_file, ref));
    print("image mean, plates x 0.3, direct (pbrt maxdepth 1)", ratio(direct, ref));
    print("image mean, plates x 0.3, pbrt maxdepth 2", ratio(depth3, ref));
    print("image mean, plates x 0.3, pbrt maxdepth 3 (the file's)", ratio(full, ref));
    print("wall, plates x 0.3, direct", wall(direct));
    print("wall, plates x 0.3, pbrt maxdepth 3", wall(full));
    print("floor, plates x 0.3, direct", floor(direct));
    print("floor, plates x 0.3, pbrt maxdepth 2", floor(depth3));
    print("floor, plates x 0.3, pbrt maxdepth 3", floor(full));
    // The three rougher plates (alpha 0.05, 0.1, 0.25): ours is dimmer at the highlights' centres
    // and wider (GGX's long tails); our estimator is not the cause: BSDF sampling alone agrees.
    auto rough = [&](const Image& a, const Image& b) { return ratio(a, b, 0.25, 0.52, 0.80, 0.92); };
    const Image bsdf_only = render_small(s, 256, 2, Sampling::BsdfOnly);
    print("rough plates, plates x 0.3, direct", rough(direct, ref));
    print("rough plates: NEE + MIS / BSDF sampling alone (256 spp)", rough(direct, bsdf_only));
    // Tungsten's veach-bidir gives its rough conductor Beckmann's distribution, which pbrt-v4
    // cannot express (docs/reference-deviations-veach-bidir.md): the same suspicion here.
    for (const char* m : {"Smooth", "Glossy", "Rough", "SuperRough"}) material(s, m).microfacet = Material::Microfacet::Beckmann;
    const Image beckmann = render_small(s, 64, 2);
    print("rough plates, plates x 0.3 and Beckmann, direct", rough(beckmann, ref));
    print("top plate's highlights, plates x 0.3 and Beckmann, direct", plate(beckmann));
    print("image mean, plates x 0.3 and Beckmann, direct", ratio(beckmann, ref));
    CHECK(rough(direct, ref).y < 0.9);
    CHECK(within(rough(beckmann, ref), 0.02));
    CHECK(within(rough(direct, bsdf_only), 0.03));
    CHECK(plate(as_file).y > 3.0);
    CHECK(within(plate(direct), 0.03));
    CHECK(within(floor(direct), 0.06));
    CHECK(floor(full).y > 1.15);
}

TEST_CASE("reference deviations: staircase2's colour shift is its stand-in wood, not the glass's medium", "[.][reference-deviations]") {
    if (!have("staircase2")) return;
    // textures/wood5.tga, the stairs' texture, is an 8 x 8 mid-grey stand-in (210 bytes, every
    // value 128) where the reference has red-brown wood. Two renders with the same seed, the stairs
    // once nearly black and once nearly white, differ exactly in the pixels whose paths touch the
    // stairs; over the pixels they leave alone, the colour shift is gone.
    Scene s = load("staircase2", 128);
    const Image ref = reference("staircase2", s.film.width, s.film.height);
    const Image as_file = render_small(s, 64, s.film.max_depth);
    Material& wood = material(s, "Wood");
    const Material file_wood = wood;
    wood.albedo_texture = -1;
    wood.albedo = glm::vec3(0.05f);
    const Image dark = render_small(s, 64, s.film.max_depth);
    wood.albedo = glm::vec3(0.9f);
    const Image light = render_small(s, 64, s.film.max_depth);
    glm::dvec3 a(0.0), b(0.0);
    int untouched = 0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x)
            if (dark.at(x, y) == light.at(x, y)) {
                a += glm::dvec3(as_file.at(x, y));
                b += glm::dvec3(ref.at(x, y));
                ++untouched;
            }
    std::printf("staircase2, 128 px, 64 spp: ours / reference, r g b\n");
    print("image mean, as the file says", ratio(as_file, ref));
    std::printf("  pixels whose paths never touch the stairs: %d of %d\n", untouched, ref.width * ref.height);
    print("those pixels' mean", a / b);
    // The medium we ignore: "green", sigma_a (0.5, 0.2, 0.4) per unit, fills glass panels 0.031 to
    // 0.037 units thick (Mesh014.ply's three boxes). As a tint of exp(-sigma_a 0.037 / 2) per
    // crossing of a face (two per pass through a panel), which overstates every path but the
    // most oblique, it moves the image mean by less than half a percent.
    Material& glass = material(s, "Glass");
    glass.albedo = glm::vec3(std::exp(-0.5f * 0.0185f), std::exp(-0.2f * 0.0185f), std::exp(-0.4f * 0.0185f));
    wood = file_wood;
    const Image tinted = render_small(s, 64, s.film.max_depth);
    print("image mean with the medium as a tint / without", ratio(tinted, as_file));
    CHECK(untouched > 200);
    CHECK(std::fabs(ratio(as_file, ref).x - ratio(as_file, ref).z) > 0.03);
    CHECK(within(a / b, 0.02));
    CHECK(within(ratio(tinted, as_file), 0.005));
}

TEST_CASE("reference deviations: kitchen's blinds transmit (pbrt's diffusetransmission)", "[.][reference-deviations]") {
    if (!have("kitchen")) return;
    // The blinds before the window, as the importer reads them now and with their transmission
    // dropped (as it read them before issue 31): the image mean and the blocks over the window.
    Scene s = load("kitchen", 160);
    const Image ref = reference("kitchen", s.film.width, s.film.height);
    const Image now = render_small(s, 64, s.film.max_depth);
    material(s, "Blinds").transmittance = glm::vec3(0.0f);
    const Image dropped = render_small(s, 64, s.film.max_depth);
    auto window = [&](const Image& im) { return ratio(im, ref, 0.70, 0.0, 0.90, 0.18); };
    std::printf("kitchen, 160 px, 64 spp: ours / reference, r g b\n");
    print("image mean, transmission dropped", ratio(dropped, ref));
    print("image mean, transmission kept", ratio(now, ref));
    print("the window's blocks, transmission dropped", window(dropped));
    print("the window's blocks, transmission kept", window(now));
    CHECK(window(now).y > window(dropped).y);
    CHECK(ratio(now, ref).y > ratio(dropped, ref).y);
}

TEST_CASE("reference deviations: classroom rebuilt z-up, its sky under Rotate and ConcatTransform, renders as the original", "[.][reference-deviations]") {
    if (!have("classroom")) return;
    // The world under `Rotate 90 1 0 0` (y up -> z up), the camera under the inverse turn, and every
    // world `Transform` (absolute) made a `ConcatTransform`, so the sky light sits under `Rotate` +
    // pbrt-v3's z-up matrix: the same picture, if the importer composes the light's transforms
    // and writes the map's frame right.
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sweeptrace-zup-classroom";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::filesystem::create_directory_symlink(bitterli("classroom") / "models", dir / "models");
    std::filesystem::create_directory_symlink(bitterli("classroom") / "textures", dir / "textures");
    std::ifstream in(bitterli("classroom") / "scene-v4.pbrt");
    std::ofstream out(dir / "scene-v4.pbrt");
    std::string line;
    bool world = false, camera_turned = false;
    while (std::getline(in, line)) {
        if (world) {
            const std::size_t t = line.find("Transform [");
            if (t != std::string::npos && (t == 0 || line[t - 1] == ' ')) line.insert(t, "Concat");
        }
        out << line << "\n";
        if (!world && !camera_turned && line.rfind("Transform [", 0) == 0) {
            out << "Rotate -90 1 0 0\n";
            camera_turned = true;
        }
        if (line.rfind("WorldBegin", 0) == 0) {
            out << "Rotate 90 1 0 0\n";
            world = true;
        }
    }
    out.close();
    REQUIRE(camera_turned);
    std::vector<std::string> warnings;
    Scene z = load_pbrt_scene(dir / "scene-v4.pbrt", false, warnings);
    z.film.height = static_cast<int>(std::lround(static_cast<double>(z.film.height) * 160 / z.film.width));
    z.film.width = 160;
    const Scene y = load("classroom", 160);
    const glm::dvec3 r = ratio(render_small(z, 32, 4), render_small(y, 32, 4));
    std::printf("classroom rebuilt z-up / the original, 160 px, 32 spp, depth 4\n");
    print("image mean", r);
    std::filesystem::remove_all(dir);
    CHECK(within(r, 0.01));
}

TEST_CASE("reference deviations: kitchen's blinds are Tungsten's transparency, alpha 0.612 over a lambert", "[.][reference-deviations]") {
    if (!have("kitchen")) return;
    // The scene's Tungsten form (111116/toyray-scenes, kitchen/scene.json, commit 0e1de82c) gives
    // the blinds "transparency" with alpha 0.612066 over a lambert of albedo (0.612, 0.4995,
    // 0.3787): a hit is the lambert with probability alpha and otherwise passes straight through,
    // unchanged (neutral). The pbrt-v4 file has diffusetransmission 0.3/0.25/0.2 instead, and
    // pbrt-v4 has no such material. We have no stochastic transparency either, so the experiment
    // mixes two renders, alpha x (blinds an opaque lambert) + (1 - alpha) x (blinds removed):
    // exact for light that meets the blinds once (the camera's view of the blinds lit from
    // behind), only approximate for light that crosses them more than once.
    Scene s = load("kitchen", 160);
    const Image ref = reference("kitchen", s.film.width, s.film.height);
    // The blinds as the camera sees them, over the window (image fractions at 160 x 90).
    auto blinds = [&](const Image& im) { return ratio(im, ref, 0.625, 0.111, 0.875, 0.222); };
    const Image as_file = render_small(s, 64, s.film.max_depth);
    Material& m = material(s, "Blinds");
    m.transmittance = glm::vec3(0.0f);
    m.albedo = glm::vec3(0.6120656f, 0.4995053f, 0.3786763f);
    const Image opaque = render_small(s, 64, s.film.max_depth);
    Scene open = s;
    const std::uint32_t index = material_index(open, "Blinds");
    std::erase_if(open.objects, [&](const Object& o) { return o.material == index; });
    const Image gone = render_small(open, 64, s.film.max_depth);
    const float alpha = 0.612066f;
    Image mix(ref.width, ref.height);
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) mix.at(x, y) = alpha * opaque.at(x, y) + (1.0f - alpha) * gone.at(x, y);
    std::printf("kitchen, 160 px, 64 spp: ours / reference, r g b\n");
    print("the blinds, as the pbrt-v4 file says (diffusetransmission)", blinds(as_file));
    print("the blinds, an opaque lambert (Tungsten's base alone)", blinds(opaque));
    print("the blinds, removed", blinds(gone));
    print("the blinds, alpha x lambert + (1 - alpha) x removed", blinds(mix));
    print("image mean, as the file says", ratio(as_file, ref));
    print("image mean, the mix (light crossing the blinds twice: approximate)", ratio(mix, ref));
    CHECK(blinds(as_file).y < 0.7);
    CHECK(within(blinds(mix), 0.15));
}

TEST_CASE("reference deviations: coffee's silver handle is Tungsten's mirror of albedo 1, the pot's band is light trapped by its silver ring", "[.][reference-deviations]") {
    if (!have("coffee")) return;
    // The scene's Tungsten form (111116/toyray-scenes, coffee/scene.json, commit 9e68a8d8) gives
    // "Metal" as "mirror", albedo 1: no Fresnel term at all, where the pbrt-v4 file has pbrt's
    // silver conductor (normal reflectance about 0.95, bluer loss). Its plastics are smooth
    // ("plastic"; the file's coateddiffuse roughness 0.001), which changes nothing measurable.
    // Depth: Tungsten's max_bounces 16 is our 16 (see reference-deviations.md: its path tracer
    // counts every surface hit, the light's included, as ours does).
    Scene s = load("coffee", 200);
    const Image ref = reference("coffee", s.film.width, s.film.height);
    auto handle = [&](const Image& im) { return coffee_handle(im, ref); };
    auto band = [&](const Image& im) { return coffee_band(im, ref); };
    const Image as_file = render_small(s, 128, 16);
    coffee_tungsten_mirror(s);
    const Image mirror = render_small(s, 128, 16);
    std::printf("coffee, 200 px, 128 spp, depth 16: ours / reference, r g b\n");
    print("the handle, silver conductor (the pbrt-v4 file)", handle(as_file));
    print("the handle, mirror of albedo 1 (Tungsten's form)", handle(mirror));
    print("image mean, silver conductor", ratio(as_file, ref));
    print("image mean, mirror of albedo 1", ratio(mirror, ref));
    CHECK(handle(as_file).z < 0.96);
    CHECK(within(handle(mirror), 0.02));
    // The band: the ring (models/Mesh015.ply) is a closed silver tube whose inner wall lies on the
    // glass's outer surface (within 0.1 mm), a mirror glued to the glass: light in the glass wall
    // under it is kept in and leaves late, so the band keeps brightening with the path depth long
    // after the rest of the image has converged, and without the ring it converges. Why the
    // reference holds less: Tungsten's 0.5 mm ray epsilon skips that mirror (the next test case).
    std::printf("the band above the pot's ring (mirror of albedo 1) by our path depth:\n");
    const Image d9 = render_small(s, 128, 9), d13 = render_small(s, 128, 13), d25 = render_small(s, 128, 25);
    print("depth 9", band(d9));
    print("depth 13", band(d13));
    print("depth 16 (Tungsten's max_bounces 16)", band(mirror));
    print("depth 25", band(d25));
    print("image mean, depth 25 / depth 16", ratio(d25, mirror));
    Scene ringless = s;
    const std::uint32_t index = material_index(ringless, "Metal");
    // The file's two silver shapes, in its order: the ring (Mesh015.ply), then the handle.
    const auto ring = std::find_if(ringless.objects.begin(), ringless.objects.end(), [&](const Object& o) { return o.material == index; });
    REQUIRE(ring != ringless.objects.end());
    ringless.objects.erase(ring);
    const Image r13 = render_small(ringless, 128, 13), r25 = render_small(ringless, 128, 25);
    print("without the ring, depth 13", band(r13));
    print("without the ring, depth 25", band(r25));
    // Tungsten's form shades the ring smooth with the mesh's own normals, as we do. Does the
    // excess come from the interpolated normals (a mirror reflecting about a normal that is not
    // the face's sends light on other courses)? The ring with its faces' own normals:
    Scene faceted = s;
    const auto faceted_ring = std::find_if(faceted.objects.begin(), faceted.objects.end(), [&](const Object& o) { return o.material == index; });
    if (const auto* instance = std::get_if<MeshInstance>(&faceted_ring->shape)) faceted.meshes[instance->mesh].vertex_normals.clear();
    const Image f16 = render_small(faceted, 128, 16), f25 = render_small(faceted, 128, 25);
    print("the ring's faces' own normals, depth 16", band(f16));
    print("the ring's faces' own normals, depth 25", band(f25));
    CHECK(band(mirror).y > 1.3);
    CHECK(band(d9).y < 1.0);
    CHECK(band(d25).y > band(mirror).y + 0.15);
    CHECK(std::fabs(band(r25).y - band(r13).y) < 0.06);
}

namespace {

// Tungsten's ray epsilon, applied from outside the renderer: every ray Tungsten spawns from a
// surface (TraceBase.cpp, ray.scatter(hitpoint, wo, info.epsilon), and its shadow rays) ignores
// hits nearer than info.epsilon along the ray, and TraceableScene.hpp sets info.epsilon to a fixed
// DefaultEpsilon = 5e-4 scene units for every finite primitive (tunabrain/tungsten at a3233951;
// TriangleMesh::intersectionInfo leaves it). We leave a surface by its rounding-error bound
// instead. This wrapper raises every query's tmin to epsilon / |dir|: coffee's camera is at least
// 0.19 m from every surface, so only rays leaving a surface are changed, as in Tungsten.
// `skips` picks which objects may be skipped (all of them is Tungsten); a skipped hit is counted
// per object.
class CoffeeEpsilonAccel : public Accel {
public:
    CoffeeEpsilonAccel(const Accel& inner, float epsilon, std::vector<bool> skips)
        : inner_(inner), epsilon_(epsilon), skips_(std::move(skips)), skipped_(skips_.size()) {}
    using Accel::intersect;
    using Accel::occluded;
    bool intersect(const collision::Ray& ray, SurfaceHit& hit) const override {
        collision::Ray r = ray;
        const float near = epsilon_ / std::sqrt(glm::dot(r.dir, r.dir));
        while (inner_.intersect(r, hit)) {
            if (hit.t >= near || !skips_[hit.object]) return true;
            ++skipped_[hit.object];
            r.tmin = hit.t;  // strictly beyond the skipped hit (the query is tmin < t)
        }
        return false;
    }
    bool occluded(const collision::Ray& ray) const override {
        SurfaceHit hit;
        return intersect(ray, hit);
    }
    std::size_t memory_bytes() const override { return inner_.memory_bytes(); }
    std::string name() const override { return "tungsten-epsilon"; }
    std::uint64_t skipped(std::size_t object) const { return skipped_[object].load(); }

private:
    const Accel& inner_;
    float epsilon_;
    std::vector<bool> skips_;
    mutable std::vector<std::atomic<std::uint64_t>> skipped_;
};

}  // namespace

TEST_CASE("reference deviations: coffee's band is Tungsten's 0.5 mm ray epsilon skipping the silver ring glued to the glass", "[.][reference-deviations]") {
    if (!have("coffee")) return;
    // Geometry (models/Mesh015.ply against Mesh010.ply): the ring is a closed silver tube of
    // rectangular section, r 0.0706 to 0.0716, y 0.0361 to 0.0462 (64 segments). Its inner wall
    // (face centres r 0.07058 to 0.07066) coincides with the glass's outer surface (face centres
    // 0.07054 to 0.07064, vertices to 0.07072, 126 segments): within 0.1 mm, a fifth of
    // Tungsten's epsilon. So in Tungsten a ray leaving the glass there skips the mirror glued to
    // it, and one reflected by that mirror skips the glass surface it sits on.
    Scene s = load("coffee", 200);
    coffee_tungsten_mirror(s);  // the handle's cause (experiment above)
    const Image ref = reference("coffee", s.film.width, s.film.height);
    auto band = [&](const Image& im) { return coffee_band(im, ref); };
    auto handle = [&](const Image& im) { return coffee_handle(im, ref); };
    const std::uint32_t metal_index = material_index(s, "Metal");
    // The file's two silver shapes, in its order: the ring (Mesh015.ply), then the handle.
    std::size_t ring = s.objects.size();
    for (std::size_t i = 0; i < s.objects.size() && ring == s.objects.size(); ++i)
        if (s.objects[i].material == metal_index) ring = i;
    REQUIRE(ring < s.objects.size());
    const auto bvh = make_accel(AccelKind::Bvh, s);
    auto render_with = [&](const Accel& accel, int depth) {
        RenderOptions o;
        o.spp = 128;
        o.max_depth = depth;
        o.seed = 7;
        o.sampler = s.film.sampler;
        return render(s, accel, o).image;
    };
    auto only = [&](auto pick) {
        std::vector<bool> v(s.objects.size());
        for (std::size_t i = 0; i < v.size(); ++i) v[i] = pick(i);
        return v;
    };
    const Image ours16 = render_with(*bvh, 16);
    const CoffeeEpsilonAccel tungsten(*bvh, 5e-4f, only([](std::size_t) { return true; }));
    const Image t16 = render_with(tungsten, 16);
    const CoffeeEpsilonAccel tungsten25(*bvh, 5e-4f, only([](std::size_t) { return true; }));
    const Image t25 = render_with(tungsten25, 25);
    std::printf("coffee, 200 px, 128 spp, Metal a mirror of albedo 1: ours / reference, r g b\n");
    print("band, depth 16, our offsets", band(ours16));
    print("band, depth 16, Tungsten's epsilon 5e-4", band(t16));
    print("band, depth 25, Tungsten's epsilon 5e-4", band(t25));
    print("handle, depth 16, Tungsten's epsilon 5e-4", handle(t16));
    print("image mean, depth 16, our offsets", ratio(ours16, ref));
    print("image mean, depth 16, Tungsten's epsilon 5e-4", ratio(t16, ref));
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < s.objects.size(); ++i) total += tungsten.skipped(i);
    std::printf("  hits skipped by the epsilon at depth 16: %llu; by object (1 %% or more):\n", static_cast<unsigned long long>(total));
    for (std::size_t i = 0; i < s.objects.size(); ++i)
        if (100 * tungsten.skipped(i) >= total)
            std::printf("    %-40s %-16s %5.1f %%\n", s.objects[i].name.c_str(), s.materials[s.objects[i].material].name.c_str(),
                        100.0 * double(tungsten.skipped(i)) / double(total));
    // Which skip matters: the epsilon on the ring's hits only, and on every hit but the ring's.
    const CoffeeEpsilonAccel ring_only(*bvh, 5e-4f, only([&](std::size_t i) { return i == ring; }));
    const CoffeeEpsilonAccel but_ring(*bvh, 5e-4f, only([&](std::size_t i) { return i != ring; }));
    const Image ring16 = render_with(ring_only, 16), rest16 = render_with(but_ring, 16);
    print("band, depth 16, epsilon on the ring's hits only", band(ring16));
    print("band, depth 16, epsilon on every hit but the ring's", band(rest16));
    CHECK(band(ours16).y > 1.3);
    CHECK(within(band(t16), 0.05));
    CHECK(!within(ratio(ours16, ref), 0.01));
    CHECK(within(ratio(t16, ref), 0.01));
    // Both glued collars matter, pulling opposite ways: the ring's skip alone loses light, the
    // others' alone (mostly the black collar's) add it.
    CHECK(band(ring16).y < 0.98);
    CHECK(band(rest16).y > 1.6);
}

TEST_CASE("reference deviations: coffee matches at the reference check's settings with Tungsten's mirror and ray epsilon", "[.][reference-deviations]") {
    if (!have("coffee")) return;
    // The reference check's own settings for coffee (docs/reference-scenes.md: quarter size,
    // 1024 spp of independent samples, box pixel filter, depth 16, seed 1), and its block test,
    // with the two things Tungsten's form and code do differently: Metal a mirror of albedo 1, and
    // the 5e-4 ray epsilon (CoffeeEpsilonAccel above). About 140 CPU s.
    Scene s = load("coffee", 200);
    s.film.filter = FilterSpec{};
    coffee_tungsten_mirror(s);
    const DownsampledReference ref = downsample_reference(read_image(bitterli("coffee") / "TungstenRender.exr"), 4);
    REQUIRE(ref.image.width == s.film.width);
    REQUIRE(ref.image.height == s.film.height);
    const auto bvh = make_accel(AccelKind::Bvh, s);
    const CoffeeEpsilonAccel tungsten(*bvh, 5e-4f, std::vector<bool>(s.objects.size(), true));
    auto check = [&](const Accel& accel) {
        RenderOptions o;
        o.spp = 1024;
        o.max_depth = 16;
        o.seed = 1;
        o.sampler = SamplerKind::Independent;
        const RenderResult r = render(s, accel, o);
        return compare_blocks(r.image, r.variance, ref.image, ref.variance, ref.valid);
    };
    const BlockComparison mirror = check(*bvh), both = check(tungsten);
    std::printf("coffee, 200 x 250, 1024 spp, depth 16, the reference check's block test:\n");
    std::printf("  %-40s %s\n", "", "mean ratio r g b        |z| < 3  |z| < 5  median block error");
    for (const auto& [what, b] : {std::pair<const char*, const BlockComparison&>{"mirror, our offsets", mirror},
                                  std::pair<const char*, const BlockComparison&>{"mirror, Tungsten's epsilon 5e-4", both}})
        std::printf("  %-40s %.4f %.4f %.4f  %5.1f %%  %5.1f %%  %+.2f %%\n", what, b.mean_ratio.x, b.mean_ratio.y,
                    b.mean_ratio.z, 100.0 * b.share_within_3, 100.0 * b.share_within_5, 100.0 * b.median_relative_error);
    CHECK(mirror.share_within_3 < 0.95);
    CHECK(within(both.mean_ratio, 0.01));
    CHECK(both.share_within_3 >= 0.97);
}

// The environment light (render/lights/environment_light.hpp), in both layouts and mirrored: its
// sampling density integrates to 1, is the one pdf() reports and follows the map; a constant map
// renders as the constant background does; a white furnace under a uniform map; NEE+MIS against
// BSDF-only under a map with a bright spot; .hdr loading with the mapping and mirror keys.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "convergence_harness.hpp"
#include "environment_test_maps.hpp"
#include "raytracer/render/lights/environment_light.hpp"
#include "raytracer/render/sampling/equal_area_octahedral.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

constexpr double kPiD = 3.14159265358979323846;

glm::vec3 sphere_dir(double theta, double phi) {
    return glm::vec3(glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
}

using Mapping = Background::EnvironmentMapping;

// The texel a world direction falls in, by the header's statement of the mapping written again
// here: the turn undone, then the mirror, then the layout.
int texel_of(const Background& bg, const glm::vec3& dir) {
    const Image& img = *bg.environment;
    const float a = -bg.rotate_degrees * kPi / 180.0f, c = std::cos(a), sn = std::sin(a);
    glm::vec3 d(c * dir.x + sn * dir.z, dir.y, -sn * dir.x + c * dir.z);
    if (bg.mirror) d.x = -d.x;
    double u = 0.0, v = 0.0;
    if (bg.mapping == Mapping::Equirect) {
        u = 0.5 + std::atan2(d.x, -d.z) / (2 * kPiD);
        v = std::acos(std::clamp(double(d.y), -1.0, 1.0)) / kPiD;
    } else {
        const glm::vec2 p = equal_area_sphere_to_square({d.x, -d.z, d.y});  // pbrt's z-up light space
        u = p.x;
        v = p.y;
    }
    const int i = std::clamp(int(u * img.width), 0, img.width - 1), j = std::clamp(int(v * img.height), 0, img.height - 1);
    return j * img.width + i;
}

// The sampling weight the header states for texel (i, j): luminance x sin(theta_j) (equirect),
// luminance alone (equal-area).
double texel_weight(const Background& bg, int i, int j) {
    const double lum = luminance(bg.scale * bg.environment->at(i, j));
    return bg.mapping == Mapping::Equirect ? lum * std::sin((j + 0.5) * kPiD / bg.environment->height) : lum;
}

// The solid-angle density of a texel of weight `weight` along `dir`: p(u, v) / (2 pi^2 sin(theta))
// or p(u, v) / (4 pi), p(u, v) = weight / mean weight.
double stated_pdf(const Background& bg, double weight, double mean, const glm::vec3& dir) {
    if (bg.mapping == Mapping::EqualArea) return weight / mean / (4 * kPiD);
    const double sin_theta = std::sqrt(double(dir.x) * dir.x + double(dir.z) * dir.z);  // the turn keeps it
    return weight / mean / (2 * kPiD * kPiD * sin_theta);
}

}  // namespace

TEST_CASE("environment: for each mapping, mirrored or not, the density integrates to 1, is the one sampled with, "
          "and samples follow the map", "[render][environment]") {
    const int combo = GENERATE(0, 1, 2, 3);
    const Mapping mapping = combo < 2 ? Mapping::Equirect : Mapping::EqualArea;
    const bool mirror = combo % 2 == 1;
    const int w = 16, h = mapping == Mapping::Equirect ? 8 : 16;
    const Background bg = env_background(environment_test_map(w, h), 30.0f, 2.0f, mapping, mirror);
    INFO("equal-area " << (mapping == Mapping::EqualArea) << ", mirror " << mirror);
    const EnvironmentLight env(bg);
    REQUIRE(env.emits());
    // Integral of pdf over the sphere by a midpoint rule much finer than the texels (pdf is
    // piecewise constant in (u, v), divided by sin(theta) for equirect, which the measure cancels).
    const int nt = 8 * 64, np = 16 * 64;
    double integral = 0.0;
    for (int a = 0; a < nt; ++a)
        for (int b = 0; b < np; ++b) {
            const double theta = (a + 0.5) * kPiD / nt, phi = (b + 0.5) * 2 * kPiD / np;
            integral += env.pdf(sphere_dir(theta, phi)) * std::sin(theta) * (kPiD / nt) * (2 * kPiD / np);
        }
    CHECK(integral == Approx(1.0).epsilon(2e-3));  // texel edges cut through the quadrature cells

    // Sampled directions fall in texels with probability w_ij / sum w.
    std::vector<double> expected(static_cast<std::size_t>(w * h));
    double sum = 0.0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) sum += expected[static_cast<std::size_t>(j * w + i)] = texel_weight(bg, i, j);
    const double mean = sum / (w * h);
    constexpr int n = 200000;
    std::vector<int> hist(expected.size(), 0);
    Rng rng(5, 0, 0);
    for (int s = 0; s < n; ++s) {
        glm::vec3 dir, le;
        float pdf = 0.0f;
        if (!env.sample(rng.uniform(), rng.uniform(), dir, pdf, le)) continue;
        const int k = texel_of(bg, dir);
        // The MIS density is the sampled one, and both are the header's density of that texel.
        if (mapping == Mapping::EqualArea) REQUIRE(pdf == env.pdf(dir));
        REQUIRE(pdf == Approx(env.pdf(dir)).epsilon(1e-3));
        REQUIRE(pdf == Approx(stated_pdf(bg, expected[static_cast<std::size_t>(k)], mean, dir)).epsilon(1e-3));
        REQUIRE(le == environment_radiance(bg, dir));  // what a ray escaping along dir sees
        REQUIRE(le == 2.0f * bg.environment->pixels[static_cast<std::size_t>(k)]);
        ++hist[static_cast<std::size_t>(k)];
    }
    double chi2 = 0.0;
    int dof = -1;
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const double e = expected[k] / sum * n;
        if (expected[k] == 0.0) {
            CHECK(hist[k] == 0);
            continue;
        }
        chi2 += (hist[k] - e) * (hist[k] - e) / e;
        ++dof;
    }
    CHECK(chi2 < dof + 6.0 * std::sqrt(2.0 * dof));  // ~ p 1e-6 for ~110 (equirect) or ~220 degrees of freedom
}

TEST_CASE("environment: a constant map renders as the constant background of the same colour", "[render][environment]") {
    // Equirect 8 x 4; equal-area 8 x 8, mirrored: its density is luminance / (4 pi) alone.
    const Mapping mapping = GENERATE(Mapping::Equirect, Mapping::EqualArea);
    const bool equal_area = mapping == Mapping::EqualArea;
    INFO("equal-area " << equal_area);
    auto flat = std::make_shared<Image>(8, equal_area ? 8 : 4);
    for (auto& p : flat->pixels) p = glm::vec3(0.6f, 0.7f, 0.9f);
    Background colour;
    colour.color = glm::vec3(0.6f, 0.7f, 0.9f) * 1.5f;
    const RenderResult a = render_with(spheres_under(env_background(flat, 70.0f, 1.5f, mapping, equal_area), 32),
                                       AccelKind::Bvh, 64, 5, 1);
    const RenderResult b = render_with(spheres_under(colour, 32), AccelKind::Bvh, 64, 5, 2);
    const BlockTestResult t = renders_agree(a, b);
    INFO(t.summary());
    CHECK(t.pass());
    // The test can fail: the map at another scale is rejected.
    const RenderResult c = render_with(spheres_under(env_background(flat, 0.0f, 1.4f, mapping), 32), AccelKind::Bvh, 64, 5, 3);
    CHECK_FALSE(renders_agree(c, b).pass());
}

TEST_CASE("environment: white furnace, a diffuse sphere under a uniform map reads rho L", "[render][environment][furnace]") {
    constexpr int size = 24;
    const Mapping mapping = GENERATE(Mapping::Equirect, Mapping::EqualArea);
    INFO("equal-area " << (mapping == Mapping::EqualArea));
    auto flat = std::make_shared<Image>(6, mapping == Mapping::EqualArea ? 6 : 3);
    for (auto& p : flat->pixels) p = glm::vec3(1.0f, 0.5f, 0.25f);
    Scene scene = empty_scene(size, size);
    scene.background = env_background(flat, 10.0f, 1.0f, mapping);
    const float rho = 0.6f;
    add_object(scene, collision::Sphere{glm::vec3(0.0f), 1.0f}, add_material(scene, diffuse(rho)), glm::mat4(1.0f), "ball");
    scene.camera.position = {0.0f, 0.0f, 3.5f};
    scene.camera.vfov_degrees = 25.0f;  // the sphere covers the frame's middle
    Image truth(size, size);
    std::vector<std::uint8_t> mask(truth.pixels.size(), 0);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double dx = x + 0.5 - size / 2.0, dy = y + 0.5 - size / 2.0;
            if (dx * dx + dy * dy < 0.3 * size * size / 4) mask[y * size + x] = 1;  // well inside the silhouette
            truth.at(x, y) = rho * glm::vec3(1.0f, 0.5f, 0.25f);
        }
    for (AccelKind accel : {AccelKind::Bvh, AccelKind::Embree}) {
        const RenderResult r = render_with(scene, accel, 32, 4, 9);
        const BlockTestResult t = test_against_truth(truth, r, 2, 1e-5, &mask);
        INFO((accel == AccelKind::Bvh ? "bvh: " : "embree: ") << t.summary());
        CHECK(t.pass());
        CHECK(t.blocks_tested > 20);
    }
}

TEST_CASE("environment: NEE+MIS and BSDF-only agree under a map with a bright texel", "[render][environment][mis]") {
    // Equirect; equal-area mirrored, where NEE's density and radiance must be the escaping ray's.
    // BSDF-only finds the bright texel in few paths, so its variance estimate is heavy-tailed:
    // at 64 / 256 spp 5 of 48 seed pairs (both layouts, mirrored or not) fail the z-test, which
    // assumes normal means; at 256 / 1024 spp on the 16 x 16 equal-area map none of 24; at
    // 1024 / 4096 the largest block z of 8 pairs is 2.6: no bias. Equal-area runs at the larger counts.
    const Mapping mapping = GENERATE(Mapping::Equirect, Mapping::EqualArea);
    const bool equal_area = mapping == Mapping::EqualArea;
    INFO("equal-area " << equal_area);
    const Background bg = equal_area ? env_background(environment_test_map(16, 16), -40.0f, 0.5f, mapping, true)
                                     : env_background(environment_test_map(32, 16), -40.0f, 0.5f);
    const Scene scene = spheres_under(bg, 32);
    const int spp = equal_area ? 256 : 64;
    const RenderResult mis = render_with(scene, AccelKind::Bvh, spp, 4, 31, Sampling::NeeMis);
    const RenderResult bsdf = render_with(scene, AccelKind::Bvh, 4 * spp, 4, 32, Sampling::BsdfOnly);
    const BlockTestResult t = renders_agree(mis, bsdf);
    INFO(t.summary());
    CHECK(t.pass());
    const RenderResult embree = render_with(scene, AccelKind::Embree, spp, 4, 33, Sampling::NeeMis);
    CHECK(renders_agree(mis, embree).pass());
}

TEST_CASE("environment: a Radiance .hdr map loads through the scene's background key", "[scene][environment]") {
    test::TempDir dir;
    // 4 x 2 uncompressed RGBE (a width below 8 is never run-length encoded): mantissas 128 and
    // exponent 129 encode 1.0; the second row is 0.5 (exponent 128).
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
    for (int i = 0; i < 4; ++i) hdr += std::string{char(128), char(128), char(128), char(129)};
    for (int i = 0; i < 4; ++i) hdr += std::string{char(128), char(128), char(128), char(128)};
    dir.write("sky.hdr", hdr);
    const Scene s = load_scene(dir.write("env.json", R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
        "film": { "width": 4, "height": 4 }, "materials": {}, "objects": [],
        "background": { "environment": { "file": "sky.hdr", "rotate": 90, "scale": 2 } } })"));
    REQUIRE(s.background.kind == Background::Kind::Environment);
    CHECK(s.background.environment->width == 4);
    CHECK(s.background.environment->at(0, 0) == glm::vec3(1.0f));
    CHECK(s.background.environment->at(3, 1) == glm::vec3(0.5f));
    CHECK(s.background.rotate_degrees == 90.0f);
    CHECK(environment_radiance(s.background, {0.0f, 1.0f, 0.0f}) == glm::vec3(2.0f));
    CHECK(environment_radiance(s.background, {0.0f, -1.0f, 0.0f}) == glm::vec3(1.0f));
}

TEST_CASE("environment: \"mirror\" and \"mapping\" load through the scene's background key", "[scene][environment]") {
    test::TempDir dir;
    // 4 x 4 uncompressed RGBE: column i's mantissas 128 + 32 i give 1, 1.25, 1.5, 1.75 at exponent
    // 129 (rows 0, 1), half that at exponent 128 (rows 2, 3).
    std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n";
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const char m = char(128 + 32 * i);
            hdr += std::string{m, m, m, char(j < 2 ? 129 : 128)};
        }
    dir.write("square.hdr", hdr);
    auto load = [&dir](const std::string& keys) {
        return load_scene(dir.write("env.json", R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
            "film": { "width": 4, "height": 4 }, "materials": {}, "objects": [],
            "background": { "environment": { "file": "square.hdr")" + keys + " } } }"));
    };
    const Scene plain = load("");
    CHECK(plain.background.mapping == Mapping::Equirect);
    CHECK_FALSE(plain.background.mirror);
    const Scene s = load(R"(, "mapping": "equal-area", "scale": 2)");
    REQUIRE(s.background.mapping == Mapping::EqualArea);
    CHECK_FALSE(s.background.mirror);
    // Toward +X and a little up and toward +Z: w = (0.99, -0.099, 0.099), (u, v) = (0.944, 0.470),
    // texel (3, 1); mirrored, w.x < 0 and u = 1 - 0.944: texel (0, 1).
    const glm::vec3 d = glm::normalize(glm::vec3(1.0f, 0.1f, 0.1f));
    CHECK(environment_radiance(s.background, d) == glm::vec3(2.0f * 1.75f));
    const Scene m = load(R"(, "mapping": "equal-area", "mirror": true, "scale": 2)");
    CHECK(m.background.mirror);
    CHECK(environment_radiance(m.background, d) == glm::vec3(2.0f * 1.0f));
    // Toward -Z (and a little +X) is near the bottom edge's middle: (u, v) = (0.532, 0.968), texel (2, 3).
    CHECK(environment_radiance(s.background, glm::normalize(glm::vec3(0.1f, 0.0f, -1.0f))) == glm::vec3(2.0f * 0.75f));
    CHECK(load(R"(, "mapping": "equirect", "mirror": false)").background.mapping == Mapping::Equirect);
    // "rotate" as an axis and degrees: about +Y it is the number form's turn; about +X it tips the
    // map's pole (the equal-area centre, texel (1..2, 1..2) = 1.25 and 1.5) from +Y toward +Z.
    const Scene turned_y = load(R"(, "rotate": {"axis": [0, 1, 0], "degrees": 30})");
    const Scene number_y = load(R"(, "rotate": 30)");
    const Scene unturned = load("");
    Rng rng(9, 0, 0);
    int differ = 0, differ_unturned = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 dir = glm::normalize(glm::vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
        const glm::vec3 a = environment_radiance(turned_y.background, dir);
        // The same turn in float through another route: texels can differ only right at their edges.
        differ += a != environment_radiance(number_y.background, dir);
        differ_unturned += a != environment_radiance(unturned.background, dir);
    }
    CHECK(differ <= 2);
    CHECK(differ_unturned > 50);  // the map varies enough for the comparison to mean something
    const Scene tipped = load(R"(, "mapping": "equal-area", "rotate": {"axis": [1, 0, 0], "degrees": 90})");
    CHECK(environment_radiance(tipped.background, glm::normalize(glm::vec3(0.01f, -0.01f, 1.0f))) == glm::vec3(1.5f));
    CHECK(environment_radiance(s.background, glm::normalize(glm::vec3(0.01f, 1.0f, 0.01f))) == glm::vec3(2.0f * 1.5f));
}

// Noise forensics (render/film/path_forensics.hpp): the image is the same bit for bit with it on, the
// report is the same at 1 and 3 threads, the credits add up to the samples' second moment and
// mean exactly as the header states, the path types are the ones the scene can make, and a
// region keeps at most kRegionTypes keys however many the paths make.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "convergence_harness.hpp"
#include "raytracer/render/film/path_forensics.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// Grey everywhere (so a sample's luminance is its red channel): a white quad light facing down
// onto a diffuse floor, a mirror ball on it, seen from the side; the light itself in view.
Scene lit_room() {
    Scene s = empty_scene(40, 24);
    s.camera.position = {0.0f, 0.6f, 4.0f};
    s.camera.look_at = {0.0f, 0.7f, 0.0f};
    add_object(s, collision::Quad{{-3.0f, 0.0f, -3.0f}, {0.0f, 0.0f, 6.0f}, {6.0f, 0.0f, 0.0f}},
               add_material(s, diffuse(0.5f)), glm::mat4(1.0f), "floor");
    Material mirror;
    mirror.type = Material::Type::Metal;
    mirror.albedo = glm::vec3(0.9f);
    mirror.roughness = 0.0f;
    mirror.name = "mirror";
    add_object(s, collision::Sphere{{0.5f, 0.5f, 0.0f}, 0.5f}, add_material(s, mirror), glm::mat4(1.0f), "ball");
    Material lamp;
    lamp.type = Material::Type::Emissive;
    lamp.emission = glm::vec3(4.0f);
    add_object(s, collision::Quad{{-1.0f, 1.6f, -0.5f}, {1, 0, 0}, {0, 0, 1}}, add_material(s, lamp), glm::mat4(1.0f), "lamp");
    return s;
}

// A closed box of white diffuse walls, a rough and a smooth white metal ball and a small lamp,
// seen from inside: nothing absorbs, so paths run to max_depth mixing D, G and S vertices, and
// nearly every long path is a path type of its own.
Scene mixed_box(int max_depth) {
    Scene s = empty_scene(8, 8);
    s.film.max_depth = max_depth;
    s.camera.position = {0.0f, 0.0f, 1.5f};
    s.camera.look_at = {0.0f, 0.0f, -1.0f};
    add_object(s, collision::Aabb{{0.0f, 0.0f, 0.0f}, {4.0f, 4.0f, 4.0f}}, add_material(s, diffuse(1.0f)), glm::mat4(1.0f), "walls");
    Material gloss;
    gloss.type = Material::Type::Metal;
    gloss.albedo = glm::vec3(1.0f);
    gloss.roughness = 0.3f;
    add_object(s, collision::Sphere{{1.0f, -1.0f, -1.0f}, 0.5f}, add_material(s, gloss), glm::mat4(1.0f), "gloss");
    Material mirror = gloss;
    mirror.roughness = 0.0f;
    add_object(s, collision::Sphere{{-1.0f, -1.0f, -1.0f}, 0.5f}, add_material(s, mirror), glm::mat4(1.0f), "mirror");
    Material lamp;
    lamp.type = Material::Type::Emissive;
    lamp.emission = glm::vec3(1.0f);
    add_object(s, collision::Sphere{{0.0f, 1.0f, -1.0f}, 0.2f}, add_material(s, lamp), glm::mat4(1.0f), "lamp");
    return s;
}

struct Run {
    RenderResult result;
    std::string json;
    PathForensics::Totals totals;
    std::vector<PathForensics::Row> types;
    std::size_t most_keys = 0;
};

Run run(const Scene& scene, const Accel& accel, int threads, bool on, int max_depth = 4, int spp = 6) {
    RenderOptions o;
    o.spp = spp;
    o.max_depth = max_depth;
    o.seed = 5;
    o.threads = threads;
    o.sampler = SamplerKind::Independent;  // the variance image is then the samples' own
    PathForensics f(scene);
    if (on) o.forensics = &f;
    Run r{render(scene, accel, o), {}, {}, {}, 0};
    if (on) {
        r.json = f.json(o.spp);
        r.totals = f.totals();
        r.types = f.rows(true, 100);
        r.most_keys = f.most_region_keys();
    }
    return r;
}

// The credits' sums against the result: sum of X = spp * sum of pixel means; sum of X^2 from the
// unbiased variance of each pixel's mean, var * spp * (spp - 1) + spp * mean^2 (red channel =
// luminance, the scenes being grey).
void check_sums(const Run& r, int spp) {
    double sum_x = 0.0, sum_x2 = 0.0;
    for (std::size_t i = 0; i < r.result.image.pixels.size(); ++i) {
        const double m = r.result.image.pixels[i].r, v = r.result.variance.pixels[i].r;
        sum_x += spp * m;
        sum_x2 += v * spp * (spp - 1) + spp * m * m;
    }
    CHECK(r.totals.first == Approx(sum_x).epsilon(1e-4));
    CHECK(r.totals.second == Approx(sum_x2).epsilon(1e-4));
}

}  // namespace

TEST_CASE("forensics: the image is unchanged bit for bit, and the report is the same at 1 and 3 threads",
          "[render][forensics]") {
    const Scene scene = lit_room();
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const Run off = run(scene, *accel, 1, false);
    const Run one = run(scene, *accel, 1, true);
    const Run three = run(scene, *accel, 3, true);
    CHECK(same_bits(off.result.image, one.result.image));
    CHECK(same_bits(off.result.image, three.result.image));
    CHECK(one.json == three.json);
    CHECK(one.json.find("\"regions\"") != std::string::npos);
}

TEST_CASE("forensics: the credits sum to the samples' second moment and mean, and name only possible path types",
          "[render][forensics]") {
    const Scene scene = lit_room();
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const int spp = 32;
    const Run r = run(scene, *accel, 2, true, 4, spp);
    CHECK(r.totals.samples == r.result.image.pixels.size() * spp);
    check_sums(r, spp);
    // The variance credits, sum over passes 2..n of X (X - m), have the mean (n - 1) Var X per
    // pixel; the unbiased sample variance s^2 = var * spp estimates Var X from the same samples.
    double expected_variance = 0.0;
    for (const glm::vec3& v : r.result.variance.pixels) expected_variance += (spp - 1) * double(v.r) * spp;
    INFO("variance credits " << r.totals.variance << ", (n - 1) s^2 summed " << expected_variance);
    CHECK(r.totals.variance > 0.7 * expected_variance);
    CHECK(r.totals.variance < 1.3 * expected_variance);
    // Diffuse floor, mirror ball, emitter: D and S vertices only, and the lamp is in view (L E).
    std::set<std::string> seen;
    for (const PathForensics::Row& row : r.types) {
        seen.insert(row.path);
        INFO(row.path);
        CHECK(row.path.find('G') == std::string::npos);
        CHECK(row.path.rfind("L ", 0) == 0);
    }
    CHECK(seen.count("L E") == 1);
    CHECK(seen.count("L D E") == 1);
    CHECK(seen.count("L D S E") == 1);  // the floor's light in the mirror
    // Depth 1 shows the emitter alone.
    const Run direct = run(scene, *accel, 1, true, 1);
    REQUIRE(direct.types.size() == 1);
    CHECK(direct.types[0].path == "L E");
    CHECK(direct.types[0].second == Approx(1.0));
}

TEST_CASE("forensics: a region keeps at most kRegionTypes keys, the rest as \"other types\", and the sums still add up",
          "[render][forensics]") {
    const Scene scene = mixed_box(40);
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const int spp = 8;
    const Run r = run(scene, *accel, 2, true, 40, spp);
    // 64 samples a pass, each with up to 30 new keys: far more than a region keeps.
    CHECK(r.most_keys <= PathForensics::kRegionTypes + 1);
    CHECK(r.most_keys > PathForensics::kRegionTypes / 2);
    bool other = false;
    for (const PathForensics::Row& row : r.types) other = other || row.path == "other types";
    CHECK(other);
    check_sums(r, spp);
    // The choice of keys is made in one order: the same report at any thread count.
    CHECK(run(scene, *accel, 1, true, 40, spp).json == r.json);
}

// film.clamp_sample (pbrt-v4's film maxcomponentvalue): each camera sample's radiance is scaled so
// its largest component is at most the limit, before the filter's weight; off, the render is the
// same bit for bit. The importer writes it from maxcomponentvalue.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "convergence_harness.hpp"
#include "pbrt_test_support.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

// A bright emitter filling part of the view over a grey floor, a box filter (weight 1).
std::string bright_scene(const std::string& film_extra) {
    return R"({ "camera": { "position": [0, 1, 4], "look_at": [0, 0.5, 0] },
        "film": { "width": 24, "height": 16, "spp": 4, "filter": { "type": "box" })" + film_extra + R"( },
        "materials": { "lamp": { "type": "emissive", "emission": [40, 20, 10] }, "floor": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5] } },
        "objects": [ { "type": "sphere", "center": [0, 0.7, 0], "radius": 0.6, "material": "lamp" },
                     { "type": "quad", "corner": [-4, 0, -4], "edge_u": [0, 0, 8], "edge_v": [8, 0, 0], "material": "floor" } ] })";
}

}  // namespace

TEST_CASE("clamp_sample: every sample's largest component is at most the limit, its hue kept, off changes nothing", "[render][film]") {
    const test::TempDir dir;
    const Scene plain = load_scene(dir.write("a.json", bright_scene("")));
    const Scene zero = load_scene(dir.write("b.json", bright_scene("")));
    const Scene clamped = load_scene(dir.write("c.json", bright_scene(R"(, "clamp_sample": 2)")));
    CHECK(clamped.film.clamp_sample == 2.0f);
    const RenderResult a = render_with(plain, AccelKind::Bvh, 4, 4, 3), z = render_with(zero, AccelKind::Bvh, 4, 4, 3);
    const RenderResult c = render_with(clamped, AccelKind::Bvh, 4, 4, 3);
    float brightest = 0.0f, brightest_clamped = 0.0f;
    bool hue_kept = false;
    for (std::size_t i = 0; i < a.image.pixels.size(); ++i) {
        REQUIRE(a.image.pixels[i] == z.image.pixels[i]);
        const glm::vec3 p = a.image.pixels[i], q = c.image.pixels[i];
        brightest = std::max(brightest, std::max(p.x, std::max(p.y, p.z)));
        brightest_clamped = std::max(brightest_clamped, std::max(q.x, std::max(q.y, q.z)));
        // A pixel of the lamp alone (every sample 40, 20, 10) comes out as the lamp's hue at 2.
        if (p == glm::vec3(40.0f, 20.0f, 10.0f)) hue_kept = q == glm::vec3(2.0f, 1.0f, 0.5f);
    }
    CHECK(brightest > 2.0f);  // the test has something to clamp
    CHECK(brightest_clamped <= 2.0f);
    CHECK(hue_kept);
}

TEST_CASE("pbrt film: maxcomponentvalue becomes film.clamp_sample", "[pbrt][film]") {
    const test::TempDir dir;
    const auto c = test::convert_text(dir, "Film \"rgb\" \"float maxcomponentvalue\" 10\nWorldBegin\n");
    CHECK(c.warnings.empty());
    CHECK(c.doc["film"]["clamp_sample"] == 10.0);
    CHECK_FALSE(test::convert_text(dir, "Film \"rgb\"\nWorldBegin\n").doc["film"].contains("clamp_sample"));
}

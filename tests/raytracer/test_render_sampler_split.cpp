// The renderer's samples are addressed by (seed, pixel, sample index): the image is the in-order
// mean of per-sample radiances that can be computed in any order and any split of the sample
// range (what a render farm splitting [0, spp) relies on), for both samplers. And the scene's
// film.sampler key.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

#include "raytracer/input_error.hpp"
#include "raytracer/render/camera.hpp"
#include "raytracer/render/integrators/path.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/render/sampling/sampler.hpp"
#include "raytracer/scene/load_scene.hpp"
#include "render_test_scenes.hpp"
#include "scene_test_files.hpp"

using namespace sweeptrace;

namespace {

// The radiance of sample `s` of pixel (x, y), computed apart from the renderer.
glm::vec3 one_sample(const Scene& scene, const PathIntegrator& integrator, const CameraModel& camera,
                     const RenderOptions& o, int x, int y, int s) {
    PixelSampler sampler(o.sampler, o.seed, std::uint64_t(y) * scene.film.width + x, std::uint64_t(s));
    const glm::vec2 film = sampler.get2d(sample_dim::kFilm);
    const glm::vec2 lens = sampler.get2d(sample_dim::kLens);
    std::uint64_t rays = 0;
    return integrator.radiance(camera.generate(float(x) + film.x, float(y) + film.y, lens.x, lens.y), sampler, rays);
}

}  // namespace

TEST_CASE("render: per-sample radiance is the same in any order and split of the sample range", "[render][determinism]") {
    const Scene scene = test::two_light_scene(19, 13);
    const test::DoublePrecisionAccel accel(scene);
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent}) {
        RenderOptions o;
        o.spp = 12;
        o.seed = 5;
        o.threads = 2;
        o.sampler = kind;
        const RenderResult r = render(scene, accel, o);
        const LightSet lights(scene);
        const CameraModel camera(scene.camera, scene.film.width, scene.film.height);
        const PathIntegrator integrator(scene, accel, lights, o.max_depth, o.sampling, PlantedDefect::None, o.roulette);
        int compared = 0;
        for (int y = 0; y < scene.film.height; y += 3) {
            for (int x = 0; x < scene.film.width; x += 2) {
                std::vector<glm::vec3> forward, split(12);
                for (int s = 0; s < 12; ++s) forward.push_back(one_sample(scene, integrator, camera, o, x, y, s));
                for (int s = 11; s >= 5; --s) split[std::size_t(s)] = one_sample(scene, integrator, camera, o, x, y, s);
                for (int s = 0; s < 5; ++s) split[std::size_t(s)] = one_sample(scene, integrator, camera, o, x, y, s);
                REQUIRE(std::memcmp(forward.data(), split.data(), forward.size() * sizeof(glm::vec3)) == 0);
                glm::dvec3 sum(0.0);  // the renderer adds passes in sample order, in double
                for (const glm::vec3& v : forward) sum += glm::dvec3(v);
                const glm::vec3 mean(sum / 12.0);
                REQUIRE(std::memcmp(&mean, &r.image.at(x, y), sizeof mean) == 0);
                ++compared;
            }
        }
        CHECK(compared == 10 * 5);
    }
}

TEST_CASE("scene: film.sampler selects the sampler, sobol by default", "[scene][sampler]") {
    test::TempDir dir;
    const auto text = [](const std::string& film) {
        return R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "film": )" + film +
               R"(, "materials": { "m": { "type": "diffuse" } }, "objects": [{ "type": "sphere", "radius": 1, "material": "m" }] })";
    };
    CHECK(load_scene(dir.write("a.json", text(R"({ "width": 4, "height": 4 })"))).film.sampler == SamplerKind::Sobol);
    CHECK(load_scene(dir.write("b.json", text(R"({ "width": 4, "height": 4, "sampler": "independent" })"))).film.sampler ==
          SamplerKind::Independent);
    CHECK(load_scene(dir.write("c.json", text(R"({ "width": 4, "height": 4, "sampler": "sobol" })"))).film.sampler ==
          SamplerKind::Sobol);
    const auto bad = dir.write("d.json", text(R"({ "width": 4, "height": 4, "sampler": "halton" })"));
    try {
        load_scene(bad);
        FAIL("an unknown sampler loaded");
    } catch (const InputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("d.json") && Catch::Contains("film.sampler") &&
                                 Catch::Contains("unknown sampler \"halton\"") && Catch::Contains("sobol, independent"));
    }
}

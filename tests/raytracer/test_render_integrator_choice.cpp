// Choosing the light transport method: film.integrator in our JSON (default path, unknown names
// refused with the key's path), and pbrt's Integrator "bdpt" and "sppm" mapped to ours (bdpt,
// vcm with sppm's radius) with their maxdepth, without a warning.
#include <catch2/catch.hpp>

#include "pbrt_test_support.hpp"
#include "scene_load_error.hpp"

using namespace sweeptrace;
using namespace sweeptrace::test;

namespace {

std::string scene_with_film(const std::string& film_extra) {
    return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
               "film": {"width": 8, "height": 8)" + film_extra + R"(},
               "materials": {"m": {"type": "diffuse"}},
               "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
}

}  // namespace

TEST_CASE("film.integrator: path by default, bdpt or vcm on request, anything else refused", "[scene][bdpt]") {
    const TempDir dir;
    CHECK(load_scene(dir.write("a.json", scene_with_film(""))).film.integrator == IntegratorKind::Path);
    CHECK(load_scene(dir.write("b.json", scene_with_film(R"(, "integrator": "path")"))).film.integrator ==
          IntegratorKind::Path);
    CHECK(load_scene(dir.write("c.json", scene_with_film(R"(, "integrator": "bdpt")"))).film.integrator ==
          IntegratorKind::Bdpt);
    const Scene v = load_scene(dir.write("d.json", scene_with_film(R"(, "integrator": "vcm", "vcm_radius": 0.25)")));
    CHECK(v.film.integrator == IntegratorKind::Vcm);
    CHECK(v.film.vcm_radius == 0.25f);
    CHECK(load_scene(dir.write("e.json", scene_with_film(""))).film.vcm_radius == 0.0f);  // the default
    CHECK(load_error(dir, scene_with_film(R"(, "vcm_radius": 0)")).find("film.vcm_radius") != std::string::npos);
    const std::string e = load_error(dir, scene_with_film(R"(, "integrator": "sppm")"));
    CHECK(e.find("film.integrator") != std::string::npos);
    CHECK(e.find("unknown integrator \"sppm\" (known: path, bdpt, vcm)") != std::string::npos);
    CHECK(load_error(dir, scene_with_film(R"(, "integrator": 3)")).find("film.integrator") != std::string::npos);
}

TEST_CASE("pbrt Integrator \"bdpt\" becomes film.integrator bdpt with its maxdepth, without a warning", "[pbrt][bdpt]") {
    const TempDir dir;
    const auto c = convert_text(dir, "Integrator \"bdpt\" \"integer maxdepth\" 3\nWorldBegin\n");
    CHECK(c.warnings.empty());
    CHECK(c.doc["film"]["integrator"] == "bdpt");
    CHECK(c.doc["film"]["max_depth"] == 4);
    const auto p = convert_text(dir, "Integrator \"path\" \"integer maxdepth\" 3\nWorldBegin\n");
    CHECK_FALSE(p.doc["film"].contains("integrator"));  // the default, as before
}

TEST_CASE("pbrt Integrator \"sppm\" becomes film.integrator vcm with its radius and maxdepth, without a warning",
          "[pbrt][vcm]") {
    const TempDir dir;
    const auto c = convert_text(dir, "Integrator \"sppm\" \"integer maxdepth\" 4 \"float radius\" 0.05\nWorldBegin\n");
    CHECK(c.warnings.empty());
    CHECK(c.doc["film"]["integrator"] == "vcm");
    CHECK(c.doc["film"]["vcm_radius"] == Approx(0.05));
    CHECK(c.doc["film"]["max_depth"] == 5);
    // Without a radius, pbrt starts at 1 scene unit and shrinks it per pixel by photon counts: ours
    // is left to our pixel-footprint default (test_render_vcm_radius.cpp renders such a scene).
    const auto d = convert_text(dir, "Integrator \"sppm\"\nWorldBegin\n");
    CHECK(d.warnings.empty());
    CHECK_FALSE(d.doc["film"].contains("vcm_radius"));
    // mlt still has no counterpart: its warning names what is lost.
    const auto m = convert_text(dir, "Integrator \"mlt\"\nWorldBegin\n");
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0].find("sppm") != std::string::npos);
}

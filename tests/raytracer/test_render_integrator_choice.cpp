// Choosing the light transport method: film.integrator in our JSON (default path, unknown names
// refused with the key's path), and pbrt's Integrator "bdpt" mapped to ours with its maxdepth,
// without a warning.
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

TEST_CASE("film.integrator: path by default, bdpt on request, anything else refused", "[scene][bdpt]") {
    const TempDir dir;
    CHECK(load_scene(dir.write("a.json", scene_with_film(""))).film.integrator == IntegratorKind::Path);
    CHECK(load_scene(dir.write("b.json", scene_with_film(R"(, "integrator": "path")"))).film.integrator ==
          IntegratorKind::Path);
    CHECK(load_scene(dir.write("c.json", scene_with_film(R"(, "integrator": "bdpt")"))).film.integrator ==
          IntegratorKind::Bdpt);
    const std::string e = load_error(dir, scene_with_film(R"(, "integrator": "vcm")"));
    CHECK(e.find("film.integrator") != std::string::npos);
    CHECK(e.find("unknown integrator \"vcm\" (known: path, bdpt)") != std::string::npos);
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

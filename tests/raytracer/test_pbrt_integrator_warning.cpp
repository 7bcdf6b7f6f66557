// The importer's warning for a pbrt-v4 Integrator our path tracer is not: it must say what is
// really lost (issue 31 item 3), not "the same image with other noise". An mlt or lightpath
// scene's caustics from small lights stay black or extremely noisy under our path tracer, and a
// delta light seen through or in a specular surface is never reached; "path", "volpath", "bdpt"
// and "sppm" (what we have: sppm is our vcm) warn nothing.
#include <catch2/catch.hpp>

#include "pbrt_test_support.hpp"

using namespace sweeptrace;
using sweeptrace::test::convert_text;
using sweeptrace::test::has_warning;
using sweeptrace::test::TempDir;

namespace {

std::vector<std::string> warnings_for(const TempDir& dir, const std::string& integrator) {
    return convert_text(dir, "Film \"rgb\"\nSampler \"sobol\"\n" + integrator + "\nWorldBegin\n").warnings;
}

}  // namespace

TEST_CASE("pbrt Integrator mlt, lightpath: the warning names file:line and what is lost", "[pbrt]") {
    const TempDir dir;
    for (const char* type : {"mlt", "lightpath"}) {
        const std::vector<std::string> w = warnings_for(dir, std::string("Integrator \"") + type + "\" \"integer maxdepth\" 5");
        REQUIRE(w.size() == 1);
        INFO(w[0]);
        CHECK_THAT(w[0], Catch::StartsWith((dir.path() / "scene.pbrt").string() + ":3: Integrator \"" + type + "\""));
        CHECK_THAT(w[0], Catch::Contains("caustics from small lights"));
        CHECK_THAT(w[0], Catch::Contains("stay black or extremely noisy"));
        CHECK_THAT(w[0], Catch::Contains("delta light"));
        CHECK_THAT(w[0], Catch::Contains("never reached at all"));
        CHECK_THAT(w[0], !Catch::Contains("the same image with other noise"));
    }
}

TEST_CASE("pbrt Integrator path, volpath, bdpt and sppm (ours): no warning, ambientocclusion: a different quantity", "[pbrt]") {
    const TempDir dir;
    CHECK(warnings_for(dir, "Integrator \"path\" \"integer maxdepth\" 5").empty());
    CHECK(warnings_for(dir, "Integrator \"volpath\" \"integer maxdepth\" 5").empty());
    CHECK(warnings_for(dir, "Integrator \"bdpt\" \"integer maxdepth\" 5").empty());
    CHECK(warnings_for(dir, "Integrator \"sppm\" \"integer maxdepth\" 5 \"float radius\" 0.1").empty());
    CHECK(has_warning(warnings_for(dir, "Integrator \"ambientocclusion\""), "renders a different quantity"));
    CHECK(has_warning(warnings_for(dir, "Integrator \"frobnicate\""), "is not a pbrt-v4 integrator"));
}

TEST_CASE("pbrt Integrator mlt under --strict: an error, nothing converted", "[pbrt]") {
    const TempDir dir;
    CHECK_THROWS_WITH(convert_text(dir, "Integrator \"mlt\"\nWorldBegin\n", true),
                      Catch::EndsWith("(--strict makes this an error)") && Catch::Contains("never reached at all"));
}

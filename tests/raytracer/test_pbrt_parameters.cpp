// Issue 32 item 3: the pbrt-v4 parameters docs/pbrt-import.md marks supported (S), each read
// with pbrt-v4's own default: a scene that writes the default explicitly translates exactly as
// one that leaves it out, and nothing warns about the parameter. And values at the edges of
// pbrt-v4's ranges are accepted (a seed is any int, maxdepth 0, one pixel sample).
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "pbrt_test_support.hpp"

namespace {

using sweeptrace::test::convert_text;
using sweeptrace::test::TempDir;

struct Default {
    const char* statement;  // the scene, with {} where the parameter goes
    const char* parameter;  // pbrt-v4's default, written out
};

const char* kFilm = "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 8\n";

std::string with(const std::string& statement, const std::string& parameter) {
    std::string s = statement;
    s.replace(s.find("{}"), 2, parameter);
    return s;
}

// pbrt-v4 (src/pbrt/cameras.cpp, film.cpp, samplers.cpp, integrators.cpp, filters.cpp, shapes.cpp,
// lights.cpp, materials.cpp): the defaults its Create() functions pass to GetOneFloat & co.
const std::vector<Default> kDefaults = {
    {"Camera \"perspective\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float fov\" 90"},
    {"Camera \"perspective\" \"float lensradius\" 0.1 {}\nWorldBegin\nShape \"sphere\"\n", "\"float focaldistance\" 1e6"},
    {"Camera \"perspective\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float lensradius\" 0"},
    {"Camera \"perspective\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float shutteropen\" 0 \"float shutterclose\" 1"},
    {"Camera \"perspective\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float frameaspectratio\" 2"},  // 16 / 8
    {"Camera \"perspective\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float screenwindow\" [-2 2 -1 1]"},
    {"Film \"rgb\" {}\nWorldBegin\nShape \"sphere\"\n", "\"integer xresolution\" 1280 \"integer yresolution\" 720"},
    {"Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 8 {}\nWorldBegin\nShape \"sphere\"\n", "\"float iso\" 100"},
    {"Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 8 {}\nWorldBegin\nShape \"sphere\"\n", "\"string filename\" \"pbrt.exr\""},
    {"Sampler \"zsobol\" {}\nWorldBegin\nShape \"sphere\"\n", "\"integer pixelsamples\" 16"},
    {"Integrator \"path\" {}\nWorldBegin\nShape \"sphere\"\n", "\"integer maxdepth\" 5"},
    {"PixelFilter \"gaussian\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float sigma\" 0.5"},
    {"PixelFilter \"gaussian\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float xradius\" 1.5 \"float yradius\" 1.5"},
    {"PixelFilter \"box\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float xradius\" 0.5 \"float yradius\" 0.5"},
    {"PixelFilter \"mitchell\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float xradius\" 2 \"float yradius\" 2"},
    {"PixelFilter \"triangle\" {}\nWorldBegin\nShape \"sphere\"\n", "\"float xradius\" 2 \"float yradius\" 2"},
    {"WorldBegin\nShape \"sphere\" {}\n", "\"float radius\" 1"},
    {"WorldBegin\nShape \"disk\" {}\n", "\"float radius\" 1"},
    {"WorldBegin\nShape \"disk\" {}\n", "\"float height\" 0"},
    {"WorldBegin\nMaterial \"diffuse\" {}\nShape \"sphere\"\n", "\"rgb reflectance\" [0.5 0.5 0.5]"},
    {"WorldBegin\nMaterial \"dielectric\" {}\nShape \"sphere\"\n", "\"float eta\" 1.5"},
    {"WorldBegin\nMaterial \"dielectric\" {}\nShape \"sphere\"\n", "\"float roughness\" 0"},
    {"WorldBegin\nMaterial \"thindielectric\" {}\nShape \"sphere\"\n", "\"float eta\" 1.5"},
    {"WorldBegin\nMaterial \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\" {}\nShape \"sphere\"\n",
     "\"float roughness\" 0 \"bool remaproughness\" true"},
    {"WorldBegin\nMaterial \"coateddiffuse\" {}\nShape \"sphere\"\n", "\"rgb reflectance\" [0.5 0.5 0.5]"},
    {"WorldBegin\nMaterial \"coateddiffuse\" {}\nShape \"sphere\"\n", "\"float roughness\" 0 \"float eta\" 1.5"},
    {"WorldBegin\nAreaLightSource \"diffuse\" {}\nShape \"sphere\"\n", "\"float scale\" 1 \"bool twosided\" false"},
    {"WorldBegin\nLightSource \"point\" \"rgb I\" [1 1 1] {}\nShape \"sphere\"\n", "\"float scale\" 1"},
    {"WorldBegin\nLightSource \"point\" \"rgb I\" [1 1 1] {}\nShape \"sphere\"\n", "\"point3 from\" [0 0 0]"},
    {"WorldBegin\nLightSource \"spot\" \"rgb I\" [1 1 1] {}\nShape \"sphere\"\n", "\"float coneangle\" 30 \"float conedeltaangle\" 5"},
    {"WorldBegin\nLightSource \"spot\" \"rgb I\" [1 1 1] {}\nShape \"sphere\"\n", "\"point3 from\" [0 0 0] \"point3 to\" [0 0 1]"},
    {"WorldBegin\nLightSource \"distant\" \"rgb L\" [1 1 1] {}\nShape \"sphere\"\n", "\"point3 from\" [0 0 0] \"point3 to\" [0 0 1]"},
    {"WorldBegin\nLightSource \"distant\" \"rgb L\" [1 1 1] {}\nShape \"sphere\"\n", "\"float scale\" 1"},
    {"WorldBegin\nTexture \"c\" \"spectrum\" \"checkerboard\" {}\nMaterial \"diffuse\" \"texture reflectance\" \"c\"\nShape \"sphere\"\n",
     "\"float uscale\" 1 \"float vscale\" 1 \"float udelta\" 0 \"float vdelta\" 0"},
    {"WorldBegin\nTexture \"c\" \"spectrum\" \"checkerboard\" {}\nMaterial \"diffuse\" \"texture reflectance\" \"c\"\nShape \"sphere\"\n",
     "\"rgb tex1\" [1 1 1] \"rgb tex2\" [0 0 0]"},
};

}  // namespace

TEST_CASE("pbrt parameters: every supported parameter written with pbrt-v4's default translates as when left out", "[pbrt][issue32]") {
    TempDir dir;
    for (const Default& d : kDefaults) {
        const std::string statement = d.statement;
        const bool has_film = statement.rfind("Film", 0) == 0;
        const std::string head = has_film ? "" : kFilm;
        const std::string explicit_text = head + with(statement, d.parameter);
        const std::string implicit_text = head + with(statement, "");
        INFO(explicit_text);
        const auto a = convert_text(dir, explicit_text);
        const auto b = convert_text(dir, implicit_text);
        nlohmann::json da = a.doc, db = b.doc;
        da.erase("description"), db.erase("description");
        CHECK(da == db);
        // The parameter was read: nothing warns about it by name.
        for (const std::string& w : a.warnings) CHECK(w.find("ignored") == std::string::npos);
        CHECK(a.warnings.size() == b.warnings.size());
    }
}

TEST_CASE("pbrt parameters: values at the edges of pbrt-v4's ranges are accepted", "[pbrt][issue32]") {
    TempDir dir;
    for (const char* scene : {
             "Sampler \"zsobol\" \"integer seed\" 5\nWorldBegin\nShape \"sphere\"\n",
             "Sampler \"zsobol\" \"integer seed\" 0\nWorldBegin\nShape \"sphere\"\n",
             "Sampler \"halton\" \"integer seed\" -2147483648\nWorldBegin\nShape \"sphere\"\n",
             "Sampler \"zsobol\" \"integer seed\" 2147483647 \"integer pixelsamples\" 1\nWorldBegin\nShape \"sphere\"\n",
             "Integrator \"path\" \"integer maxdepth\" 0\nWorldBegin\nShape \"sphere\"\n",
             "Film \"rgb\" \"integer xresolution\" 1 \"integer yresolution\" 1 \"float maxcomponentvalue\" 3.4e38\nWorldBegin\nShape \"sphere\"\n",
             "Camera \"perspective\" \"float fov\" 0.001\nWorldBegin\nShape \"sphere\"\n",
             "Camera \"perspective\" \"float fov\" 179.9\nWorldBegin\nShape \"sphere\"\n",
         }) {
        INFO(scene);
        const std::string text = std::string(std::string(scene).rfind("Film", 0) == 0 ? "" : kFilm) + scene;
        const auto file = dir.write("edge.pbrt", text);
        std::vector<std::string> warnings;
        CHECK_NOTHROW(sweeptrace::load_pbrt_scene(file, true, warnings));
    }
}

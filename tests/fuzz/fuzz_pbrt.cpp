// libFuzzer: pbrt-v4 scene text -> the pbrt importer -> our JSON -> load_scene: a Scene or an
// InputError, nothing else (no crash, no other exception, no sanitizer report, no unbounded
// memory). The scene's folder holds an Include target, inc.pbrt, and a broken one, bad.pbrt, so
// `Include "inc.pbrt"` reaches a second file and its errors; Include "scene.pbrt" reaches the
// depth bound.
#include <exception>
#include <fstream>

#include "fuzz_input_file.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/pbrt/pbrt_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool includes = [] {
        std::ofstream(sweeptrace::fuzz::work_dir() / "inc.pbrt")
            << "AttributeBegin\nTranslate 0 1 0\nShape \"sphere\" \"float radius\" 0.5\nAttributeEnd\n";
        std::ofstream(sweeptrace::fuzz::work_dir() / "bad.pbrt") << "Shape \"sphere\" \"float radius\" [ 1\n";
        return true;
    }();
    (void)includes;
    const auto path = sweeptrace::fuzz::input_file("scene.pbrt", data, size);
    try {
        std::vector<std::string> warnings;
        const sweeptrace::Scene scene = sweeptrace::load_pbrt_scene(path, false, warnings);
        (void)scene;
    } catch (const sweeptrace::InputError&) {
        // the promised outcome for bad input
    }
    return 0;
}

// libFuzzer: JSON text -> load_scene -> a Scene or an InputError, nothing else (no crash, no
// other exception, no sanitizer report). The scene's folder holds a valid OBJ, m.obj, and a
// broken one, bad.obj, so `"file": "m.obj"` paths reach the mesh loader too.
#include <exception>
#include <fstream>

#include "fuzz_input_file.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/load_scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool meshes = [] {
        std::ofstream(sweeptrace::fuzz::work_dir() / "m.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n";
        std::ofstream(sweeptrace::fuzz::work_dir() / "bad.obj") << "v 0 0 0\rv 1 0 0\rf 1 2 9\r";
        return true;
    }();
    (void)meshes;
    const auto path = sweeptrace::fuzz::input_file("scene.json", data, size);
    try {
        const sweeptrace::Scene scene = sweeptrace::load_scene(path);
        (void)scene;
    } catch (const sweeptrace::InputError&) {
        // the promised outcome for bad input
    }
    return 0;
}

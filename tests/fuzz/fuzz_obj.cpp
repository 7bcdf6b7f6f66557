// libFuzzer: OBJ text -> load_obj -> a Mesh whose indices are all in range, or an InputError.
#include <cstdlib>

#include "fuzz_input_file.hpp"
#include "raytracer/input_error.hpp"
#include "raytracer/scene/obj_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = sweeptrace::fuzz::input_file("mesh.obj", data, size);
    try {
        const sweeptrace::Mesh mesh = sweeptrace::load_obj(path);
        const std::size_t n = mesh.triangles.vertices.size();
        for (const auto& t : mesh.triangles.indices)
            if (t.x >= n || t.y >= n || t.z >= n) std::abort();  // the loader promised valid indices
        if (!mesh.vertex_normals.empty() && mesh.vertex_normals.size() != n) std::abort();
    } catch (const sweeptrace::InputError&) {
    }
    return 0;
}

// libFuzzer: PLY bytes (any of its three encodings) -> parse_ply -> a Mesh whose indices are all in
// range and whose per-vertex arrays match its vertices, or an InputError.
#include <cstdlib>
#include <string>
#include <string_view>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/ply_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const sweeptrace::Mesh mesh =
            sweeptrace::parse_ply(std::string_view(reinterpret_cast<const char*>(data), size), "mesh.ply");
        const std::size_t n = mesh.triangles.vertices.size();
        if (mesh.triangles.indices.empty()) std::abort();  // "no faces" is an error, not an empty mesh
        for (const auto& t : mesh.triangles.indices)
            if (t.x >= n || t.y >= n || t.z >= n) std::abort();  // the loader promised valid indices
        if (!mesh.vertex_normals.empty() && mesh.vertex_normals.size() != n) std::abort();
        if (!mesh.vertex_uvs.empty() && mesh.vertex_uvs.size() != n) std::abort();
    } catch (const sweeptrace::InputError&) {
    }
    return 0;
}

// libFuzzer: PLY bytes (any of its three encodings) -> parse_ply -> a Mesh whose indices are all in
// range and whose per-vertex arrays match its vertices, or an InputError. Input that starts as
// gzip does (1f 8b) is inflated first (scene/gzip_file.hpp, as a mesh.ply.gz is), to at most
// 1 MiB here: the limit is a parameter, and a small one reaches its checks quickly.
#include <cstdlib>
#include <string>
#include <string_view>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/ply_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        std::string_view bytes(reinterpret_cast<const char*>(data), size);
        std::string inflated;
        if (bytes.size() >= 2 && bytes[0] == '\x1f' && bytes[1] == '\x8b') {
            inflated = sweeptrace::gunzip(bytes, "mesh.ply.gz", "mesh", std::size_t{1} << 20);
            if (inflated.size() > (std::size_t{1} << 20)) std::abort();  // the limit was promised
            bytes = inflated;
        }
        const sweeptrace::Mesh mesh = sweeptrace::parse_ply(bytes, "mesh.ply");
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

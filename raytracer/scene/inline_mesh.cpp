#include "raytracer/scene/inline_mesh.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

namespace sweeptrace {

namespace {

using scene_json::Node;

// The numbers of a flat array, `per` to an item. Elements are read straight from the document
// (a Node, with its path, is made only for the one that is wrong): meshes run to millions.
std::vector<float> flat_numbers(const Node& array, std::size_t per, const char* item) {
    const std::size_t n = array.array_size();
    if (n == 0 || n % per != 0)
        array.fail("must hold " + std::to_string(per) + " numbers per " + item + " (a multiple of " + std::to_string(per) +
                   ", at least " + std::to_string(per) + "), got " + std::to_string(n));
    std::vector<float> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const nlohmann::json& v = array.value()[i];
        const double d = v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
        const float f = static_cast<float>(d);
        if (!std::isfinite(f)) array.element(i).number();  // fails with the element's path and why
        out[i] = f;
    }
    return out;
}

}  // namespace

Mesh read_inline_mesh(const Node& object) {
    Mesh mesh;
    mesh.source = object.file();  // the file it came from: the farm's identity hashes it, outputs may not overwrite it
    const std::vector<float> v = flat_numbers(object.at("vertices"), 3, "vertex");
    const std::size_t vertices = v.size() / 3;
    if (vertices > std::numeric_limits<std::uint32_t>::max()) object.at("vertices").fail("more than 2^32 - 1 vertices");
    mesh.triangles.vertices.resize(vertices);
    for (std::size_t i = 0; i < vertices; ++i) mesh.triangles.vertices[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};

    const Node indices = object.at("indices");
    const std::size_t n = indices.array_size();
    if (n == 0 || n % 3 != 0)
        indices.fail("must hold 3 vertex numbers per triangle (a multiple of 3, at least 3), got " + std::to_string(n));
    mesh.triangles.indices.resize(n / 3);
    for (std::size_t i = 0; i < n; ++i) {
        const nlohmann::json& x = indices.value()[i];
        std::uint32_t index = 0;
        if (x.is_number_unsigned() && x.get<std::uint64_t>() < vertices) {
            index = static_cast<std::uint32_t>(x.get<std::uint64_t>());
        } else if (x.is_number_integer() && x.get<std::int64_t>() >= 0 && static_cast<std::uint64_t>(x.get<std::int64_t>()) < vertices) {
            index = static_cast<std::uint32_t>(x.get<std::int64_t>());
        } else {
            indices.element(i).integer(0, static_cast<std::int64_t>(vertices) - 1);  // fails: not an integer, or out of range
        }
        mesh.triangles.indices[i / 3][static_cast<int>(i % 3)] = index;
    }

    if (auto normals = object.find("normals")) {
        const std::vector<float> nv = flat_numbers(*normals, 3, "normal");
        if (nv.size() != v.size())
            normals->fail("must give one normal per vertex: " + std::to_string(nv.size() / 3) + " for " + std::to_string(vertices) + " vertices");
        mesh.vertex_normals.resize(vertices);
        for (std::size_t i = 0; i < vertices; ++i) {
            const glm::vec3 nrm(nv[3 * i], nv[3 * i + 1], nv[3 * i + 2]);
            const float len = glm::length(nrm);
            if (!(len > 0.0f) || !std::isfinite(len))
                normals->fail("normal " + std::to_string(i) + " (elements " + std::to_string(3 * i) + " to " + std::to_string(3 * i + 2) +
                              ") has no direction (its length is zero, or too large for float)");
            mesh.vertex_normals[i] = nrm / len;
        }
    }
    if (auto uvs = object.find("uvs")) {
        const std::vector<float> uv = flat_numbers(*uvs, 2, "vertex");
        if (uv.size() / 2 != vertices)
            uvs->fail("must give one (u, v) per vertex: " + std::to_string(uv.size() / 2) + " for " + std::to_string(vertices) + " vertices");
        mesh.vertex_uvs.resize(vertices);
        for (std::size_t i = 0; i < vertices; ++i) mesh.vertex_uvs[i] = {uv[2 * i], uv[2 * i + 1]};
    }
    return mesh;
}

}  // namespace sweeptrace

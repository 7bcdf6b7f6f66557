#include "raytracer/scene/obj_loader.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "raytracer/input_error.hpp"
#include "raytracer/load_budget.hpp"
#include "raytracer/scene/gzip_file.hpp"
#include "raytracer/scene/obj_outline.hpp"
#include "raytracer/scene/text_file.hpp"

namespace sweeptrace {

namespace {

// Every face tinyobjloader read is the face on its line, with the same corners, and every `v` is
// a vertex: from here on, indices and corner counts can be trusted and faces have their lines.
void agree_with_outline(const tinyobj::ObjReader& reader, const ObjOutline& outline, std::size_t vertex_count,
                        const std::string& name) {
    if (vertex_count != outline.vertex_count)
        throw InputError(name + ": tinyobjloader read " + std::to_string(vertex_count) + " vertices, the file has " +
                         std::to_string(outline.vertex_count) + " `v` lines");
    std::size_t face = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t indices = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            if (face >= outline.face_corners.size()) throw InputError(name + ": tinyobjloader read more faces than `f` lines");
            if (corners != outline.face_corners[face])
                throw InputError(name + ": line " + std::to_string(outline.face_lines[face]) + ": tinyobjloader read " +
                                 std::to_string(corners) + " corners, the line has " +
                                 std::to_string(outline.face_corners[face]));
            indices += corners;
            ++face;
        }
        if (indices != shape.mesh.indices.size())
            throw InputError(name + ": tinyobjloader returned " + std::to_string(shape.mesh.indices.size()) +
                             " face indices for " + std::to_string(indices) + " corners");
    }
    if (face != outline.face_corners.size())
        throw InputError(name + ": tinyobjloader read " + std::to_string(face) + " faces, the file has " +
                         std::to_string(outline.face_corners.size()) + " `f` lines");
}

// A face corner's texture coordinate index: -1 is "none" (then the mesh has no uv), anything else
// must be in range.
template <class Where>
void check_texcoord(int index, std::size_t count, bool& all_uvs, Where where) {
    if (index < 0) {
        if (index != -1) throw InputError(where() + ": texture coordinate index out of range");
        all_uvs = false;
    } else if (static_cast<std::size_t>(index) >= count) {
        throw InputError(where() + ": texture coordinate index out of range (refers to vt " + std::to_string(index + 1) +
                         ", the file has " + std::to_string(count) + ")");
    }
}

struct VertexKey {
    int v, n, t;
    bool operator==(const VertexKey&) const = default;
};
struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const {
        return std::hash<std::uint64_t>()((static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.v)) << 32) ^
                                          (static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.n)) << 16) ^
                                          static_cast<std::uint32_t>(k.t));
    }
};

std::string first_line(const std::string& s) {
    std::string out = s.substr(0, s.find('\n'));
    while (!out.empty() && (out.back() == '\r' || out.back() == ' ')) out.pop_back();
    return out;
}

}  // namespace

Mesh load_obj(const std::filesystem::path& file, ObjOutline* outline_out) {
    const FileBytes file_bytes = read_maybe_gzipped(file, "mesh", kMaxMeshFileBytes);
    const std::string& text = file_bytes.bytes;
    const std::string name = file.string();
    const ObjOutline outline = outline_obj(text, name);

    // triangulate = false: tinyobjloader's triangulation reads vertex positions before anyone has
    // checked the indices; we check them first and split polygons ourselves.
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // From a string, so that an `mtllib` line cannot make it open other files: materials come
    // from the scene, not the OBJ.
    if (!reader.ParseFromString(text, std::string(), config))
        throw InputError(name + ": invalid OBJ: " + excerpt(reason_or(first_line(reader.Error()).c_str(), "tinyobjloader failed"), 160));

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const std::size_t vertex_count = attrib.vertices.size() / 3;
    const std::size_t normal_count = attrib.normals.size() / 3;
    const std::size_t texcoord_count = attrib.texcoords.size() / 2;
    agree_with_outline(reader, outline, vertex_count, name);
    if (outline.face_lines.empty()) throw InputError(name + ": contains no faces (no `f` lines), nothing to render");
    auto face_where = [&](std::size_t face) { return "line " + std::to_string(outline.face_lines[face]); };

    // First pass: every index in range, and do all corners carry a usable normal?
    bool all_normals = normal_count > 0;
    bool all_uvs = texcoord_count > 0;
    std::size_t face = 0;
    std::uint64_t triangles = 0, corner_count = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            triangles += corners - 2u;
            corner_count += corners;
            for (std::size_t k = 0; k < corners; ++k) {
                const tinyobj::index_t& idx = shape.mesh.indices[offset + k];
                if (idx.vertex_index < 0 || static_cast<std::size_t>(idx.vertex_index) >= vertex_count)
                    throw InputError(name + ": " + face_where(face) + ": vertex index out of range (refers to vertex " +
                                     std::to_string(static_cast<long long>(idx.vertex_index) + 1) + ", the file has " +
                                     std::to_string(vertex_count) + ")");
                if (idx.normal_index < 0) {
                    // A relative index (-k) past the start also lands below 0; only -1 means "none".
                    if (idx.normal_index != -1)
                        throw InputError(name + ": " + face_where(face) + ": normal index out of range");
                    all_normals = false;
                } else if (static_cast<std::size_t>(idx.normal_index) >= normal_count) {
                    throw InputError(name + ": " + face_where(face) + ": normal index out of range (refers to normal " +
                                     std::to_string(idx.normal_index + 1) + ", the file has " +
                                     std::to_string(normal_count) + ")");
                }
                check_texcoord(idx.texcoord_index, texcoord_count, all_uvs, [&] { return name + ": " + face_where(face); });
            }
            offset += corners;
            ++face;
        }
    }

    // tinyobjloader's arrays, and our mesh: at most one vertex (position, normal, uv) per corner.
    charge_load_memory((attrib.vertices.size() + attrib.normals.size() + attrib.texcoords.size()) * sizeof(float) +
                           corner_count * (sizeof(tinyobj::index_t) + sizeof(glm::vec3) * 2 + sizeof(glm::vec2)) +
                           triangles * sizeof(glm::uvec3),
                       name, std::to_string(face) + " faces as " + std::to_string(triangles) + " triangles");
    for (std::size_t v = 0; v < vertex_count; ++v)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(attrib.vertices[3 * v + static_cast<std::size_t>(c)]))
                throw InputError(name + ": vertex " + std::to_string(v + 1) + " has a coordinate that is not finite");
    std::vector<glm::vec3> unit_normals;
    if (all_normals) {
        unit_normals.reserve(normal_count);
        for (std::size_t n = 0; n < normal_count && all_normals; ++n) {
            const glm::dvec3 d(attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]);
            const double len = glm::length(d);
            if (!std::isfinite(len) || len == 0.0) all_normals = false;  // unusable: shade flat instead
            else unit_normals.push_back(glm::vec3(d / len));
        }
    }

    for (std::size_t t = 0; t < texcoord_count && all_uvs; ++t)
        if (!std::isfinite(attrib.texcoords[2 * t]) || !std::isfinite(attrib.texcoords[2 * t + 1]))
            throw InputError(name + ": texture coordinate " + std::to_string(t + 1) + " is not finite");
    // Second pass: one output vertex per distinct (position, normal, uv) triple actually used.
    Mesh mesh;
    mesh.source = name;
    std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> remap;
    auto vertex_for = [&](const tinyobj::index_t& idx) {
        const VertexKey key{idx.vertex_index, all_normals ? idx.normal_index : 0, all_uvs ? idx.texcoord_index : 0};
        const auto [it, inserted] = remap.try_emplace(key, static_cast<std::uint32_t>(mesh.triangles.vertices.size()));
        if (inserted) {
            const std::size_t v = static_cast<std::size_t>(idx.vertex_index);
            mesh.triangles.vertices.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1],
                                                 attrib.vertices[3 * v + 2]);
            if (all_normals) mesh.vertex_normals.push_back(unit_normals[static_cast<std::size_t>(idx.normal_index)]);
            if (all_uvs) {
                const std::size_t t = static_cast<std::size_t>(idx.texcoord_index);
                mesh.vertex_uvs.emplace_back(attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]);
            }
        }
        return it->second;
    };
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            const std::uint32_t first = vertex_for(shape.mesh.indices[offset]);
            std::uint32_t previous = vertex_for(shape.mesh.indices[offset + 1]);
            for (std::size_t k = 2; k < corners; ++k) {
                const std::uint32_t current = vertex_for(shape.mesh.indices[offset + k]);
                mesh.triangles.indices.emplace_back(first, previous, current);
                previous = current;
            }
            offset += corners;
        }
    }
    if (outline_out) *outline_out = outline;
    return mesh;
}

}  // namespace sweeptrace

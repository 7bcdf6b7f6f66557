#pragma once
// Meshes for the mesh-mesh tests: small generated convex and concave meshes, and a minimal OBJ
// reader (v and f lines, polygons fanned into triangles) for the shared test meshes. The
// collision library has no OBJ reader (the renderer's scene loader owns that).
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "collision/mesh.hpp"

namespace testing {

using collision::TriangleMesh;

// Axis-aligned box, outward counter-clockwise faces.
inline TriangleMesh box_mesh(const glm::vec3& half) {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({(i & 1) ? half.x : -half.x, (i & 2) ? half.y : -half.y, (i & 4) ? half.z : -half.z});
    const unsigned q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : q) {
        m.indices.push_back({f[0], f[1], f[2]});
        m.indices.push_back({f[0], f[2], f[3]});
    }
    return m;
}

// Latitude-longitude sphere: every quad is planar (an isosceles trapezoid) and all vertices lie
// on the sphere, so the polyhedron is convex.
inline TriangleMesh uv_sphere(float r, int stacks, int slices) {
    TriangleMesh m;
    const float pi = 3.14159265358979f;
    m.vertices.push_back({0, r, 0});
    for (int i = 1; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const float th = pi * i / stacks, ph = 2 * pi * j / slices;
            m.vertices.push_back({r * std::sin(th) * std::cos(ph), r * std::cos(th), -r * std::sin(th) * std::sin(ph)});
        }
    m.vertices.push_back({0, -r, 0});
    const unsigned bottom = unsigned(m.vertices.size() - 1);
    auto at = [&](int i, int j) { return unsigned(1 + (i - 1) * slices + (j % slices)); };
    for (int j = 0; j < slices; ++j) m.indices.push_back({0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            m.indices.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.indices.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    for (int j = 0; j < slices; ++j) m.indices.push_back({bottom, at(stacks - 1, j + 1), at(stacks - 1, j)});
    return m;
}

// Torus around Y (concave).
inline TriangleMesh torus(float R, float r, int rings, int sides) {
    TriangleMesh m;
    const float pi = 3.14159265358979f;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sides; ++j) {
            const float u = 2 * pi * i / rings, v = 2 * pi * j / sides;
            m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u), r * std::sin(v), (R + r * std::cos(v)) * std::sin(u)});
        }
    auto at = [&](int i, int j) { return unsigned((i % rings) * sides + (j % sides)); };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sides; ++j) {
            m.indices.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            m.indices.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return m;
}

inline TriangleMesh transformed(TriangleMesh m, const glm::quat& q, const glm::vec3& offset) {
    for (glm::vec3& v : m.vertices) v = q * v + offset;
    return m;
}

// Minimal OBJ: "v x y z" and "f i[/..] j[/..] k[/..] ..." (1-based or negative indices).
inline TriangleMesh read_obj(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    TriangleMesh m;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v") {
            glm::vec3 v;
            ls >> v.x >> v.y >> v.z;
            m.vertices.push_back(v);
        } else if (tag == "f") {
            std::vector<unsigned> f;
            std::string tok;
            while (ls >> tok) {
                const long i = std::stol(tok.substr(0, tok.find('/')));
                f.push_back(unsigned(i > 0 ? i - 1 : long(m.vertices.size()) + i));
            }
            for (std::size_t k = 1; k + 1 < f.size(); ++k) m.indices.push_back({f[0], f[k], f[k + 1]});
        }
    }
    return m;
}

}  // namespace testing

#pragma once
// Closed test meshes built in code (octahedron, icosphere) with shared vertices, and the points
// where rays most easily leak through a non-watertight test: vertices and points on edges.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/mesh.hpp"
#include "reference_sampling.hpp"

namespace meshes {

inline collision::TriangleMesh octahedron(const glm::vec3& center, float r) {
    collision::TriangleMesh m;
    m.vertices = {center + glm::vec3(r, 0, 0), center + glm::vec3(-r, 0, 0), center + glm::vec3(0, r, 0),
                  center + glm::vec3(0, -r, 0), center + glm::vec3(0, 0, r), center + glm::vec3(0, 0, -r)};
    // Counter-clockwise seen from outside.
    m.indices = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

// Icosahedron subdivided `levels` times, vertices pushed onto the sphere; midpoints shared.
inline collision::TriangleMesh icosphere(const glm::vec3& center, float r, int levels) {
    const float p = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> unit = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                                   {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
    for (glm::vec3& v : unit) v = glm::normalize(v);
    std::vector<glm::uvec3> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<unsigned, unsigned>, unsigned> mid;
        const auto midpoint = [&](unsigned a, unsigned b) {
            const auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            unit.push_back(glm::normalize(unit[a] + unit[b]));
            const unsigned idx = unsigned(unit.size() - 1);
            mid.emplace(key, idx);
            return idx;
        };
        std::vector<glm::uvec3> next;
        for (const glm::uvec3& f : faces) {
            const unsigned ab = midpoint(f.x, f.y), bc = midpoint(f.y, f.z), ca = midpoint(f.z, f.x);
            next.insert(next.end(), {{f.x, ab, ca}, {f.y, bc, ab}, {f.z, ca, bc}, {ab, bc, ca}});
        }
        faces = std::move(next);
    }
    collision::TriangleMesh m;
    for (const glm::vec3& v : unit) m.vertices.push_back(center + r * v);
    m.indices = std::move(faces);
    return m;
}

// Every vertex, every edge's midpoint and `per_edge` random points along each edge (computed in
// float, so they lie within rounding of the edge, on either side).
inline std::vector<glm::vec3> vertex_and_edge_targets(const collision::TriangleMesh& m, sampling::Sampler& sm,
                                                      int per_edge) {
    std::vector<glm::vec3> out(m.vertices.begin(), m.vertices.end());
    std::map<std::pair<unsigned, unsigned>, bool> seen;
    for (const glm::uvec3& f : m.indices) {
        for (int e = 0; e < 3; ++e) {
            const unsigned a = f[e], b = f[(e + 1) % 3];
            if (!seen.emplace(std::minmax(a, b), true).second) continue;
            const glm::vec3 pa = m.vertices[a], pb = m.vertices[b];
            out.push_back(0.5f * (pa + pb));
            for (int k = 0; k < per_edge; ++k) out.push_back(pa + sm.uniform(0.0f, 1.0f) * (pb - pa));
        }
    }
    return out;
}

}  // namespace meshes

#include "raytracer/accuracy/tessellate.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <glm/geometric.hpp>

namespace sweeptrace::accuracy {

namespace {

using glm::vec3;

// A closed surface of revolution about +Y given by its profile: rows from the bottom pole (or
// the bottom cap centre) to the top, each row a ring of `segments` vertices (a pole is one
// vertex). profile(i) returns (radius, y, normal_r, normal_y) of row i.
struct Row {
    float radius, y, nr, ny;
};

Mesh revolve(const vec3& centre, const vec3& scale, int segments, const std::vector<Row>& rows) {
    Mesh m;
    auto& v = m.triangles.vertices;
    auto& n = m.vertex_normals;
    auto& idx = m.triangles.indices;
    std::vector<std::uint32_t> first(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) {
        first[r] = static_cast<std::uint32_t>(v.size());
        const int count = rows[r].radius == 0.0f ? 1 : segments;
        for (int s = 0; s < count; ++s) {
            const double phi = 2.0 * std::numbers::pi * s / segments;
            const vec3 dir(float(std::cos(phi)), 0.0f, float(std::sin(phi)));
            const vec3 p(rows[r].radius * dir.x, rows[r].y, rows[r].radius * dir.z);
            v.push_back(centre + scale * p);
            // Normals of a scaled surface: inverse scale, renormalised.
            n.push_back(glm::normalize(vec3(rows[r].nr * dir.x, rows[r].ny, rows[r].nr * dir.z) / scale));
        }
    }
    auto at = [&](std::size_t r, int s) { return rows[r].radius == 0.0f ? first[r] : first[r] + std::uint32_t(s % segments); };
    for (std::size_t r = 0; r + 1 < rows.size(); ++r) {
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = at(r, s), b = at(r, s + 1), c = at(r + 1, s), d = at(r + 1, s + 1);
            // Counter-clockwise seen from outside (+phi runs x -> z, i.e. clockwise seen from +Y).
            if (a != b) idx.push_back({a, c, b});
            if (c != d) idx.push_back({b, c, d});
        }
    }
    return m;
}

int segments_for(std::size_t triangles, double rows_per_segment) {
    // triangles ~ 2 * segments * rows, rows = rows_per_segment * segments.
    return std::max(4, int(std::lround(std::sqrt(double(triangles) / (2.0 * rows_per_segment)))));
}

// Rows of a sphere of radius r from latitude theta0 up to theta1 (-pi/2 = bottom pole); a row at
// a pole is a single vertex.
std::vector<Row> sphere_rows(int rings, float r, float y_offset, double theta0, double theta1) {
    std::vector<Row> rows;
    for (int i = 0; i <= rings; ++i) {
        const double theta = theta0 + (theta1 - theta0) * i / rings;
        const float cr = float(std::cos(theta)), sr = float(std::sin(theta));
        const bool pole = (i == 0 && theta0 == -std::numbers::pi / 2) || (i == rings && theta1 == std::numbers::pi / 2);
        rows.push_back({pole ? 0.0f : r * cr, y_offset + r * sr, pole ? 0.0f : cr, sr});
    }
    return rows;
}

}  // namespace

Mesh tessellate(const collision::Sphere& s, std::size_t triangles) {
    const int segments = segments_for(triangles, 0.5);
    const auto rows = sphere_rows(segments / 2, s.radius, 0.0f, -std::numbers::pi / 2, std::numbers::pi / 2);
    return revolve(s.center, vec3(1.0f), segments, rows);
}

Mesh tessellate(const collision::Ellipsoid& e, std::size_t triangles) {
    const int segments = segments_for(triangles, 0.5);
    const auto rows = sphere_rows(segments / 2, 1.0f, 0.0f, -std::numbers::pi / 2, std::numbers::pi / 2);
    return revolve(e.center, e.radii, segments, rows);
}

Mesh tessellate(const collision::Cylinder& c, std::size_t triangles) {
    // Side rings spaced about as far apart as the segments; caps are fans to a centre vertex.
    const double ring_ratio = std::max(0.05, double(c.height) / (2.0 * std::numbers::pi * c.radius));
    const int segments = segments_for(triangles, ring_ratio + 0.1);
    const int rings = std::max(1, int(std::lround(ring_ratio * segments)));
    std::vector<Row> rows;
    const float h = 0.5f * c.height;
    rows.push_back({0.0f, -h, 0.0f, -1.0f});  // bottom cap centre
    // The rim appears twice: once with the cap's normal, once with the side's, so the crease
    // stays sharp under smooth shading (the two rims share positions bit for bit: watertight).
    rows.push_back({c.radius, -h, 0.0f, -1.0f});
    for (int i = 0; i <= rings; ++i) rows.push_back({c.radius, -h + c.height * float(i) / float(rings), 1.0f, 0.0f});
    rows.push_back({c.radius, h, 0.0f, 1.0f});
    rows.push_back({0.0f, h, 0.0f, 1.0f});
    Mesh m = revolve(c.center, vec3(1.0f), segments, rows);
    // Rows 1-2 and rows (rings+2)-(rings+3) coincide in position: drop their zero-area strips.
    auto& idx = m.triangles.indices;
    const auto& v = m.triangles.vertices;
    idx.erase(std::remove_if(idx.begin(), idx.end(),
                             [&](const glm::uvec3& t) {
                                 return glm::length(glm::cross(v[t.y] - v[t.x], v[t.z] - v[t.x])) == 0.0f;
                             }),
              idx.end());
    return m;
}

Mesh tessellate(const collision::Capsule& c, std::size_t triangles) {
    const int segments = segments_for(triangles, 0.5 + double(c.height) / (2.0 * std::numbers::pi * c.radius));
    const int hemi = std::max(2, segments / 4);
    const int rings = std::max(1, int(std::lround(double(c.height) / (2.0 * std::numbers::pi * c.radius) * segments)));
    const float h = 0.5f * c.height;
    std::vector<Row> rows = sphere_rows(hemi, c.radius, -h, -std::numbers::pi / 2, 0.0);
    for (int i = 1; i < rings; ++i) rows.push_back({c.radius, -h + c.height * float(i) / float(rings), 1.0f, 0.0f});
    const auto top = sphere_rows(hemi, c.radius, h, 0.0, std::numbers::pi / 2);
    rows.insert(rows.end(), top.begin(), top.end());
    return revolve(c.center, vec3(1.0f), segments, rows);
}

}  // namespace sweeptrace::accuracy

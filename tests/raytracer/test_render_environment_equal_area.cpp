// The equal-area octahedral map (render/equal_area_octahedral.hpp): it round-trips and is
// equal-area (a plain octahedral map fails the same check).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "raytracer/render/equal_area_octahedral.hpp"
#include "raytracer/render/random.hpp"

using namespace sweeptrace;

namespace {

constexpr double kPiEqualArea = 3.14159265358979323846;

// The fold of the square's border: a point on an edge is one direction with its mirror image
// across that edge's middle, and the four corners are one direction (-z).
bool same_point_of_the_sphere(glm::vec2 a, glm::vec2 b, float tol) {
    auto near = [tol](glm::vec2 p, glm::vec2 q) { return std::abs(p.x - q.x) <= tol && std::abs(p.y - q.y) <= tol; };
    if (near(a, b)) return true;
    const bool vertical_edge = a.x == 0.0f || a.x == 1.0f, horizontal_edge = a.y == 0.0f || a.y == 1.0f;
    if (vertical_edge && horizontal_edge) return (b.x <= tol || b.x >= 1 - tol) && (b.y <= tol || b.y >= 1 - tol);
    if (vertical_edge) return near({a.x, 1.0f - a.y}, b);
    if (horizontal_edge) return near({1.0f - a.x, a.y}, b);
    return false;
}

// Clarberg's counterpart that is not equal-area: the octahedron |x| + |y| + |z| = 1 unfolded
// onto the square, then normalised. The equal-area check below must reject it.
glm::vec3 plain_octahedral(const glm::vec2& p) {
    const float u = 2 * p.x - 1, v = 2 * p.y - 1, z = 1 - std::abs(u) - std::abs(v);
    glm::vec3 d(u, v, z);
    if (z < 0) d = {std::copysign(1 - std::abs(v), u), std::copysign(1 - std::abs(u), v), z};
    return glm::normalize(d);
}

// Region of the sphere: one of `bands` equal z-bands (Archimedes: equal area) times one of
// `sectors` equal azimuth sectors, so all bands x sectors regions have area 4 pi / (bands sectors).
// The sectors start half a sector off the x axis: their borders then miss the square's axes and
// diagonals, where the grid's cell centres would sit exactly on them.
int sphere_region(const glm::vec3& d, int bands, int sectors) {
    const int band = std::clamp(int((d.z + 1.0) / 2.0 * bands), 0, bands - 1);
    const double turns = std::atan2(double(d.y), double(d.x)) / (2 * kPiEqualArea) + 1.0 + 0.5 / sectors;
    const int sector = int((turns - std::floor(turns)) * sectors) % sectors;
    return band * sectors + sector;
}

// Whether an n x n grid of cell centres over the square lands uniformly on the sphere's regions:
// each region's count is n^2 / regions up to the cells that straddle its border (a cell whose
// centre and corners fall in different regions may count either way; the borders are straight on
// the square, so a border that cuts a cell separates its corners), plus 4 for the few cells where
// a region's corner pokes in between the cell's corners. worst: the largest |count - n^2 /
// regions| relative to n^2 / regions (about 2 % for an equal-area map at n = 512: the borders' rows
// of cells, which the allowance covers).
bool lands_uniformly(glm::vec3 (*to_sphere)(const glm::vec2&), int n, int bands, int sectors, double& worst) {
    const int regions = bands * sectors;
    std::vector<double> count(static_cast<std::size_t>(regions), 0.0), straddling(count);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int centre = sphere_region(to_sphere({(x + 0.5f) / n, (y + 0.5f) / n}), bands, sectors);
            count[static_cast<std::size_t>(centre)] += 1;
            std::vector<int> seen{centre};
            for (int c = 0; c < 4; ++c)
                seen.push_back(sphere_region(to_sphere({float(x + c % 2) / n, float(y + c / 2) / n}), bands, sectors));
            std::sort(seen.begin(), seen.end());
            seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
            if (seen.size() > 1)
                for (int r : seen) straddling[static_cast<std::size_t>(r)] += 1;
        }
    const double expected = double(n) * n / regions;
    bool ok = true;
    worst = 0.0;
    for (int r = 0; r < regions; ++r) {
        const double excess = std::abs(count[static_cast<std::size_t>(r)] - expected) - straddling[static_cast<std::size_t>(r)] - 4;
        worst = std::max(worst, std::abs(count[static_cast<std::size_t>(r)] - expected) / expected);
        ok = ok && excess <= 0.0;
    }
    return ok;
}

}  // namespace

TEST_CASE("equal-area map: square -> sphere -> square round-trips, unit length, on a grid with its edges, corners, centre",
          "[render][environment][equal-area]") {
    constexpr int n = 64;
    // u, v in [0, 1]: 4 float ulps of 1 (measured on a 1024 grid and 2e6 random points: 1.2e-7, one ulp).
    constexpr float tol = 5e-7f;
    float worst = 0.0f, worst_length = 0.0f;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const glm::vec2 p(float(i) / n, float(j) / n);
            const glm::vec3 d = equal_area_square_to_sphere(p);
            REQUIRE(std::isfinite(d.x + d.y + d.z));
            worst_length = std::max(worst_length, std::abs(glm::length(d) - 1.0f));
            const glm::vec2 q = equal_area_sphere_to_square(d);
            INFO("(" << p.x << ", " << p.y << ") -> (" << d.x << ", " << d.y << ", " << d.z << ") -> (" << q.x << ", " << q.y << ")");
            REQUIRE(same_point_of_the_sphere(p, q, tol));
            if (i > 0 && i < n && j > 0 && j < n) worst = std::max({worst, std::abs(p.x - q.x), std::abs(p.y - q.y)});
        }
    CHECK(worst_length <= 3e-7f);  // measured 1.8e-7
    CHECK(worst <= tol);
    // The landmarks the header states: centre +z, corners -z, edges' middles on the equator.
    CHECK(equal_area_square_to_sphere({0.5f, 0.5f}) == glm::vec3(0.0f, 0.0f, 1.0f));
    for (glm::vec2 corner : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1), glm::vec2(1, 1)})
        CHECK(equal_area_square_to_sphere(corner).z == -1.0f);
    CHECK(glm::length(equal_area_square_to_sphere({1.0f, 0.5f}) - glm::vec3(1, 0, 0)) < 1e-6f);
    CHECK(glm::length(equal_area_square_to_sphere({0.5f, 1.0f}) - glm::vec3(0, 1, 0)) < 1e-6f);

    // And sphere -> square -> sphere for directions of any length, poles included.
    Rng rng(11, 0, 0);
    float worst_angle = 0.0f;
    for (int s = 0; s < 100000; ++s) {
        const glm::vec3 d = glm::vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f) * (s % 7 + 1.0f);
        if (glm::length(d) == 0.0f) continue;
        const glm::vec3 back = equal_area_square_to_sphere(equal_area_sphere_to_square(d));
        REQUIRE(std::isfinite(back.x + back.y + back.z));
        worst_angle = std::max(worst_angle, glm::length(back - glm::normalize(d)));
    }
    for (glm::vec3 pole : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1e-4f, 0, 1), glm::vec3(0, -1e-4f, -1)})
        worst_angle = std::max(worst_angle, glm::length(equal_area_square_to_sphere(equal_area_sphere_to_square(pole)) - glm::normalize(pole)));
    CHECK(worst_angle <= 1e-6f);  // measured 5.2e-7 over 2e6 random directions
}

TEST_CASE("equal-area map: a uniform grid over the square lands uniformly on the sphere (a plain octahedral map does not)",
          "[render][environment][equal-area]") {
    // 7 bands, so no band's border (a diamond on the square) runs through the grid's cell
    // centres: r^2 = 2 k / 7 is never (m / 256)^2.
    double worst = 0.0, octahedral_worst = 0.0;
    CHECK(lands_uniformly(equal_area_square_to_sphere, 512, 7, 8, worst));
    // The check can fail: the plain octahedral map crowds the grid toward the octahedron's vertices.
    CHECK_FALSE(lands_uniformly(plain_octahedral, 512, 7, 8, octahedral_worst));
    INFO("worst region off by " << worst << " (equal-area), " << octahedral_worst << " (plain octahedral)");
    CHECK(octahedral_worst > 10 * worst);
}


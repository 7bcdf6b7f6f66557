// The equal-area octahedral map (render/sampling/equal_area_octahedral.hpp) and the environment's map frame
// (render/lights/environment_light.hpp): the map round-trips and is equal-area (a plain octahedral map
// fails the same check), the frame's orientation pinned by texels whose direction is worked out
// by hand from w = (d'.x, -d'.z, d'.y), and the mirror is S = diag(-1, 1, 1) after the turn.
// Sampling, rendering and loading under both layouts: test_render_environment.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "environment_test_maps.hpp"
#include "raytracer/render/lights/environment_light.hpp"
#include "raytracer/render/sampling/equal_area_octahedral.hpp"
#include "raytracer/render/sampling/random.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

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

namespace {

using Mapping = Background::EnvironmentMapping;

// A black n x n map with one texel of radiance 1 (the rest 0).
std::shared_ptr<const Image> one_bright_texel(int n, int i, int j) {
    auto img = std::make_shared<Image>(n, n);
    img->at(i, j) = glm::vec3(1.0f);
    return img;
}

bool lit_toward(const Background& bg, glm::vec3 d) { return environment_radiance(bg, glm::normalize(d)).x > 0.0f; }

}  // namespace

TEST_CASE("environment equal-area: the map frame is w = (d'.x, -d'.z, d'.y), pinned by texels worked out by hand",
          "[render][environment][equal-area]") {
    // 5 x 5 texels, so each (u, v) below is inside a texel, not on an edge.
    // Centre (1/2, 1/2): w = +z, so d' = +Y: texel (2, 2) is straight up.
    const Background centre = env_background(one_bright_texel(5, 2, 2), 0.0f, 1.0f, Mapping::EqualArea);
    CHECK(lit_toward(centre, {0, 1, 0}));
    CHECK(lit_toward(centre, {0.1f, 1, -0.1f}));
    CHECK_FALSE(lit_toward(centre, {0, -1, 0}));
    CHECK_FALSE(lit_toward(centre, {1, 0.2f, 0}));
    // (3/4, 1/2) in texel (3, 2): in [-1, 1]^2 (1/2, 0), r = 1/2, phi = 0, so z = 1 - r^2 = 3/4 and
    // sin(theta) = r sqrt(2 - r^2) = sqrt(7)/4: w = (sqrt(7)/4, 0, 3/4), d' = (w.x, w.z, -w.y).
    const float s7 = std::sqrt(7.0f) / 4.0f;
    const Background right = env_background(one_bright_texel(5, 3, 2), 0.0f, 1.0f, Mapping::EqualArea);
    CHECK(lit_toward(right, {s7, 0.75f, 0.0f}));
    CHECK_FALSE(lit_toward(right, {-s7, 0.75f, 0.0f}));
    CHECK_FALSE(lit_toward(right, {0.0f, 0.75f, s7}));
    // Mirrored, the same texel is at S d' = (-sqrt(7)/4, 3/4, 0); turned by 90 degrees about +Y
    // (right-handed: +X goes to -Z), unmirrored, at (0, 3/4, -sqrt(7)/4).
    CHECK(lit_toward(env_background(one_bright_texel(5, 3, 2), 0.0f, 1.0f, Mapping::EqualArea, true), {-s7, 0.75f, 0.0f}));
    CHECK(lit_toward(env_background(one_bright_texel(5, 3, 2), 90.0f, 1.0f, Mapping::EqualArea), {0.0f, 0.75f, -s7}));
    // (1/2, 1/4) in texel (2, 1): in [-1, 1]^2 (0, -1/2), r = 1/2, phi = pi/2 with v < 0, so
    // w = (0, -sqrt(7)/4, 3/4) and d' = (0, 3/4, sqrt(7)/4): the top half of the image looks toward +Z.
    const Background top = env_background(one_bright_texel(5, 2, 1), 0.0f, 1.0f, Mapping::EqualArea);
    CHECK(lit_toward(top, {0.0f, 0.75f, s7}));
    CHECK_FALSE(lit_toward(top, {0.0f, 0.75f, -s7}));
    // A corner texel (0, 0) is below: w = (-, -, -) near -z, i.e. d' = (-, -, +) near -Y.
    const Background corner = env_background(one_bright_texel(5, 0, 0), 0.0f, 1.0f, Mapping::EqualArea);
    CHECK(lit_toward(corner, {-0.1f, -1.0f, 0.1f}));
    CHECK_FALSE(lit_toward(corner, {0.1f, -1.0f, 0.1f}));
    CHECK_FALSE(lit_toward(corner, {-0.1f, -1.0f, -0.1f}));
}

TEST_CASE("environment: mirror is S = diag(-1, 1, 1) after the turn, for both layouts", "[render][environment][mirror]") {
    const Mapping mapping = GENERATE(Mapping::Equirect, Mapping::EqualArea);
    const int h = mapping == Mapping::Equirect ? 16 : 32;
    const auto map = environment_test_map(32, h);
    INFO("equal-area " << (mapping == Mapping::EqualArea));
    // radiance_mirrored(d) = radiance(S d); with a turn, S R_y(-a) = R_y(a) S, so the mirrored map
    // turned by a is the plain map turned by -a, seen along S d.
    Rng rng(7, 0, 0);
    int differs = 0;
    for (int s = 0; s < 20000; ++s) {
        const glm::vec3 d = glm::normalize(glm::vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f));
        const glm::vec3 sd(-d.x, d.y, d.z);
        REQUIRE(environment_radiance(env_background(map, 0.0f, 1.0f, mapping, true), d) ==
                environment_radiance(env_background(map, 0.0f, 1.0f, mapping), sd));
        REQUIRE(environment_radiance(env_background(map, 35.0f, 1.0f, mapping, true), d) ==
                environment_radiance(env_background(map, -35.0f, 1.0f, mapping), sd));
        differs += environment_radiance(env_background(map, 0.0f, 1.0f, mapping, true), d) !=
                   environment_radiance(env_background(map, 0.0f, 1.0f, mapping), d);
    }
    CHECK(differs > 10000);  // the mirror does change what is seen (the test map is not symmetric)
    if (mapping == Mapping::Equirect) {
        // The equirect image read right to left: +X (u = 3/4) sees column u = 1/4 when mirrored.
        auto columns = std::make_shared<Image>(4, 2);
        for (int i = 0; i < 4; ++i) columns->at(i, 0) = columns->at(i, 1) = glm::vec3(float(i));
        CHECK(environment_radiance(env_background(columns, 0.0f, 1.0f), {1, 0, 0.1f}).x == 3.0f);
        CHECK(environment_radiance(env_background(columns, 0.0f, 1.0f, mapping, true), {1, 0, 0.1f}).x == 0.0f);
    }
}

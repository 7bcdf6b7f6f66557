// Object transforms from the scene's steps: quaternion rotation against Rodrigues' formula in long
// double, step order, and the normal matrix on a rotated, non-uniformly scaled object.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <variant>

#include <glm/geometric.hpp>

#include "raytracer/scene/load_scene.hpp"
#include "raytracer/scene/scene_transform.hpp"
#include "scene_test_files.hpp"

using sweeptrace::rotation_matrix;

namespace {

using LVec = std::array<long double, 3>;

// Rodrigues: R = cos θ I + sin θ [u]x + (1 - cos θ) u uᵀ, in long double: the reference.
long double rodrigues(const LVec& axis, long double degrees, int row, int col) {
    const long double len = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    const LVec u{axis[0] / len, axis[1] / len, axis[2] / len};
    const long double th = degrees * 3.14159265358979323846264338327950288L / 180.0L;
    const long double c = std::cos(th), s = std::sin(th);
    const long double cross[3][3] = {{0, -u[2], u[1]}, {u[2], 0, -u[0]}, {-u[1], u[0], 0}};
    return (row == col ? c : 0.0L) + s * cross[row][col] + (1.0L - c) * u[static_cast<std::size_t>(row)] * u[static_cast<std::size_t>(col)];
}

// The transform the loader builds for a unit sphere carrying `steps` (a JSON list).
sweeptrace::Transform loaded_transform(const std::string& steps) {
    sweeptrace::test::TempDir dir;
    const auto scene = sweeptrace::load_scene(dir.write("s.json", R"({
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
      "film": { "width": 4, "height": 4 },
      "materials": { "m": { "type": "diffuse" } },
      "objects": [{ "type": "sphere", "radius": 1, "material": "m", "transform": )" + steps + "}]}"));
    return scene.objects.at(0).transform;
}

}  // namespace

TEST_CASE("transform: quaternion rotation matches Rodrigues' formula", "[scene][transform]") {
    // Error budget per entry, in units of double epsilon e: degrees -> half-angle radians (3
    // roundings on a value <= pi: 3 pi e / 2 absolute), sin/cos (1 ulp each), normalising the axis
    // (~3 e), then at most 4 roundings forming an entry from products of numbers <= 1, doubled.
    // Summing and rounding up: 16 e.
    const double bound = 16.0 * DBL_EPSILON;
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> coord(-1.0, 1.0), angle(-360.0, 360.0);
    double worst = 0.0;
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::dvec3 axis(coord(rng), coord(rng), coord(rng));
        if (glm::length(axis) < 1e-3) continue;
        const double degrees = angle(rng);
        const glm::dmat4 m = rotation_matrix(axis, degrees);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                const long double ref = rodrigues({axis.x, axis.y, axis.z}, degrees, r, c);
                worst = std::max(worst, static_cast<double>(std::fabs(static_cast<long double>(m[c][r]) - ref)));
            }
        CHECK(m[3] == glm::dvec4(0.0, 0.0, 0.0, 1.0));
    }
    INFO("worst entry error " << worst);
    CHECK(worst <= bound);
}

TEST_CASE("transform: rotation is right-handed and steps apply in list order", "[scene][transform]") {
    const glm::dvec4 x = rotation_matrix({0.0, 1.0, 0.0}, 90.0) * glm::dvec4(1.0, 0.0, 0.0, 0.0);
    CHECK(x.x == Approx(0.0).margin(1e-15));
    CHECK(x.z == Approx(-1.0));

    const auto t = loaded_transform(R"([{ "scale": [2, 1, 1] }, { "translate": [10, 0, 0] }])");
    // Scale first, then translate: (1,0,0) -> (2,0,0) -> (12,0,0). The other order would give 22.
    const glm::vec4 p = t.to_world * glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    CHECK(p.x == 12.0f);
}

TEST_CASE("transform: normals of a rotated, non-uniformly scaled sphere come out right", "[scene][transform]") {
    const sweeptrace::Transform t = loaded_transform(R"([{ "scale": [1, 3, 0.5] },
        { "rotate": { "axis": [1, 1, 0], "degrees": 40 } }, { "translate": [2, -1, 4] }])");
    CHECK_FALSE(t.identity);

    // Reference: M = T R S, so the world normal at object point p (normal p) is R S⁻¹ p, computed
    // here in double from the same steps.
    const glm::dmat3 r(rotation_matrix({1.0, 1.0, 0.0}, 40.0));
    const glm::dvec3 inv_scale(1.0, 1.0 / 3.0, 2.0);

    // Float error: to_world is rounded once per entry (u = 2^-24), its inverse transpose is formed
    // in float by cofactors over the determinant. Perturbation of an inverse is bounded by the
    // condition number (kappa = 3 / 0.5 = 6) times the relative input error; with the cofactor
    // roundings, the direction of N n is off by at most ~10 kappa u.
    const double tol = 10.0 * 6.0 * std::ldexp(1.0, -24);
    std::mt19937 rng(99);
    std::normal_distribution<double> g;
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        const glm::dvec3 expected = glm::normalize(r * (inv_scale * n));
        const glm::dvec3 got = glm::normalize(glm::dvec3(t.normal_to_world * glm::vec3(n)));
        CHECK(glm::length(got - expected) <= tol);

        // And it is perpendicular to the surface: tangents carried by to_world.
        const glm::dvec3 t1 = glm::normalize(glm::cross(n, std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
        const glm::dvec3 t2 = glm::cross(n, t1);
        for (const glm::dvec3& tangent : {t1, t2}) {
            const glm::dvec3 world = glm::normalize(glm::dvec3(glm::mat3(t.to_world) * glm::vec3(tangent)));
            CHECK(std::fabs(glm::dot(world, got)) <= tol);
        }
    }
    // to_object undoes to_world. World coordinates here are <= 8 in magnitude; the forward
    // product errs by <= 4u per unit of that, the float inverse's entries by <= 4 kappa u, and the
    // back product amplifies by to_object's largest singular value, 2: 2 * 8 * (4 + 4 * 6) u.
    const glm::vec4 p(0.3f, -0.2f, 0.9f, 1.0f);
    const glm::vec4 back = t.to_object * (t.to_world * p);
    CHECK(glm::length(glm::vec3(back - p)) <= 2.0 * 8.0 * (4.0 + 4.0 * 6.0) * std::ldexp(1.0, -24));
}

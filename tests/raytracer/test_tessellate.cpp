// The tessellated stand-ins of analytic shapes: closed, outward, inscribed, converging in volume.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "raytracer/accuracy/mesh_compare.hpp"
#include "raytracer/accuracy/tessellate.hpp"

using namespace sweeptrace;
using namespace sweeptrace::accuracy;

namespace {

// Signed volume by the divergence theorem: positive when every face turns outward.
double volume(const collision::TriangleMesh& m) {
    double v = 0.0;
    for (std::size_t i = 0; i < m.triangle_count(); ++i) {
        const collision::Triangle t = m.triangle(i);
        v += glm::dot(glm::dvec3(t.a), glm::cross(glm::dvec3(t.b), glm::dvec3(t.c))) / 6.0;
    }
    return v;
}

void check(const Mesh& m, std::size_t wanted, double exact_volume) {
    INFO("triangles " << m.triangles.triangle_count() << " for " << wanted);
    CHECK(is_closed(m.triangles));
    CHECK(m.triangles.triangle_count() > wanted / 2);
    CHECK(m.triangles.triangle_count() < wanted * 2);
    CHECK(m.vertex_normals.size() == m.triangles.vertices.size());
    const double v = volume(m.triangles);
    // Inscribed: slightly smaller than the shape, never larger (up to float rounding).
    CHECK(v > 0.0);
    CHECK(v < exact_volume * (1.0 + 1e-5));
    if (wanted >= 10000) CHECK(v > exact_volume * 0.995);
}

}  // namespace

TEST_CASE("tessellate: sphere, ellipsoid, cylinder and capsule are closed, outward and inscribed", "[tessellate]") {
    const double pi = std::numbers::pi;
    for (std::size_t n : {100u, 1000u, 10000u, 100000u}) {
        const collision::Sphere s{{0.5f, -1.0f, 2.0f}, 1.5f};
        check(tessellate(s, n), n, 4.0 / 3.0 * pi * 1.5 * 1.5 * 1.5);
        const collision::Ellipsoid e{{0.0f, 1.0f, 0.0f}, {1.0f, 0.5f, 2.0f}};
        check(tessellate(e, n), n, 4.0 / 3.0 * pi * 1.0 * 0.5 * 2.0);
        const collision::Cylinder c{{1.0f, 0.0f, 0.0f}, 0.75f, 2.0f};
        check(tessellate(c, n), n, pi * 0.75 * 0.75 * 2.0);
        const collision::Capsule k{{0.0f, 0.0f, -1.0f}, 0.5f, 1.0f};
        check(tessellate(k, n), n, pi * 0.25 * 1.0 + 4.0 / 3.0 * pi * 0.125);
    }
    // Every vertex on the sphere.
    const collision::Sphere s{{0.5f, -1.0f, 2.0f}, 1.5f};
    for (const glm::vec3& v : tessellate(s, 5000).triangles.vertices) {
        CHECK(std::fabs(glm::length(v - s.center) - 1.5f) < 1e-5f);
    }
}

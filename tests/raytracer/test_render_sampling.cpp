// Random streams, sampling warps and the camera.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <utility>

#include <glm/geometric.hpp>

#include "raytracer/render/camera.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "render_test_stats.hpp"

using namespace sweeptrace;
using sweeptrace::test::Estimate;
using sweeptrace::test::z_bound;

TEST_CASE("rng: a stream depends only on (seed, pixel, sample), and neighbouring streams differ", "[render][rng]") {
    Rng a(7, 100, 3), b(7, 100, 3);
    for (int i = 0; i < 100; ++i) REQUIRE(a.next_u32() == b.next_u32());
    std::set<std::uint32_t> firsts;
    for (std::uint64_t seed = 0; seed < 4; ++seed)
        for (std::uint64_t pixel = 0; pixel < 16; ++pixel)
            for (std::uint64_t sample = 0; sample < 16; ++sample) firsts.insert(Rng(seed, pixel, sample).next_u32());
    // 1024 streams: a collision among 32-bit first outputs has probability ~1.2e-4.
    CHECK(firsts.size() >= 1023);
}

TEST_CASE("rng: uniform() lies in 0 <= u < 1 with mean 1/2 and variance 1/12", "[render][rng]") {
    Estimate mean, sq;
    for (std::uint64_t pixel = 0; pixel < 2000; ++pixel) {
        Rng r(1, pixel, 0);
        for (int i = 0; i < 50; ++i) {
            const float u = r.uniform();
            REQUIRE(u >= 0.0f);
            REQUIRE(u < 1.0f);
            mean.add(u);
            sq.add((u - 0.5) * (u - 0.5));
        }
    }
    CHECK(std::abs(mean.mean - 0.5) < z_bound(2) * mean.standard_error());
    CHECK(std::abs(sq.mean - 1.0 / 12.0) < z_bound(2) * sq.standard_error());
}

TEST_CASE("sampling: frames are orthonormal and right-handed, poles included", "[render][sampling]") {
    const glm::vec3 normals[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, glm::normalize(glm::vec3(1, -2, 3)),
                                 glm::normalize(glm::vec3(1e-4f, 0, -1))};
    for (const glm::vec3& n : normals) {
        const Frame f(n);
        // Each product is a few float roundings of unit quantities: 1e-6 is ~8 ulps.
        CHECK(std::abs(glm::dot(f.s, f.t)) < 1e-6f);
        CHECK(std::abs(glm::dot(f.s, f.n)) < 1e-6f);
        CHECK(std::abs(glm::dot(f.t, f.n)) < 1e-6f);
        CHECK(std::abs(glm::length(f.s) - 1.0f) < 1e-6f);
        CHECK(std::abs(glm::length(f.t) - 1.0f) < 1e-6f);
        CHECK(glm::dot(glm::cross(f.s, f.t), f.n) > 0.999f);
        const glm::vec3 v(0.3f, -0.5f, 0.8f);
        CHECK(glm::length(f.to_local(f.to_world(v)) - v) < 1e-6f);
    }
}

TEST_CASE("sampling: warps produce the densities they state", "[render][sampling]") {
    Estimate disk_area, cone, triangle_frac;
    const float omc = 0.1f;  // 1 - cos(theta_max)
    Rng rng(3, 0, 0);
    for (int i = 0; i < 200000; ++i) {
        const float u1 = rng.uniform(), u2 = rng.uniform();
        const glm::vec2 d = concentric_disk(u1, u2);
        REQUIRE(glm::dot(d, d) <= 1.0f + 1e-6f);
        const glm::vec3 h = cosine_hemisphere(u1, u2);
        REQUIRE(h.z >= 0.0f);
        const glm::vec3 c = uniform_cone(u1, u2, omc);
        REQUIRE(c.z >= 1.0f - omc - 1e-6f);
        REQUIRE(std::abs(glm::length(c) - 1.0f) < 1e-5f);
        cone.add(1.0 / uniform_cone_pdf(omc));
        // Quadrant test for uniformity on the disk: share of points with x > 0.5 is
        // (area of the circular segment) / pi.
        disk_area.add(d.x > 0.5f ? 1.0 : 0.0);
        const glm::vec2 b = uniform_triangle(u1, u2);
        REQUIRE(b.x >= 0.0f);
        REQUIRE(b.y >= 0.0f);
        REQUIRE(b.x + b.y <= 1.0f + 1e-6f);
        triangle_frac.add(b.x > 0.5f ? 1.0 : 0.0);  // the corner region b0 > 1/2 holds 1/4 of the area
    }
    const double segment = (std::acos(0.5) - 0.5 * std::sqrt(0.75)) / M_PI;
    CHECK(std::abs(disk_area.mean - segment) < z_bound(4) * disk_area.standard_error());
    // Under density cos(theta)/pi, E[cos theta] = 2/3 (E[1/pdf] would have infinite variance).
    Estimate cos_mean;
    Rng rng2(4, 0, 0);
    for (int i = 0; i < 200000; ++i) cos_mean.add(cosine_hemisphere(rng2.uniform(), rng2.uniform()).z);
    CHECK(std::abs(cos_mean.mean - 2.0 / 3.0) < z_bound(4) * cos_mean.standard_error());
    CHECK(cone.mean == Approx(2.0 * M_PI * omc).epsilon(1e-6));
    CHECK(std::abs(triangle_frac.mean - 0.25) < z_bound(4) * triangle_frac.standard_error());
}

TEST_CASE("camera: the centre ray looks at look_at, the top edge at vfov/2, the aspect follows the film", "[render][camera]") {
    Camera c;
    c.position = {1.0f, 2.0f, 3.0f};
    c.look_at = {1.0f, 2.0f, -7.0f};
    c.vfov_degrees = 60.0f;
    const CameraModel cam(c, 200, 100);
    const collision::Ray centre = cam.generate(100.0f, 50.0f, 0.5f, 0.5f);
    CHECK(glm::length(centre.origin - c.position) == 0.0f);
    CHECK(glm::length(centre.dir - glm::vec3(0, 0, -1)) < 1e-6f);
    const collision::Ray top = cam.generate(100.0f, 0.0f, 0.5f, 0.5f);
    CHECK(std::acos(-top.dir.z) == Approx(M_PI / 6.0).epsilon(1e-5));
    CHECK(top.dir.y > 0.0f);  // y grows downward on the film
    const collision::Ray right = cam.generate(200.0f, 50.0f, 0.5f, 0.5f);
    CHECK(right.dir.x / -right.dir.z == Approx(2.0 * std::tan(M_PI / 6.0)).epsilon(1e-5));
}

TEST_CASE("camera: thin lens rays through one film point meet on the focus plane", "[render][camera]") {
    Camera c;
    c.position = {0.0f, 0.0f, 0.0f};
    c.look_at = {0.0f, 0.0f, -4.0f};
    c.aperture = 0.5f;
    c.focus_distance = 3.0f;
    const CameraModel cam(c, 64, 64);
    const collision::Ray a = cam.generate(10.0f, 20.0f, 0.1f, 0.9f), b = cam.generate(10.0f, 20.0f, 0.8f, 0.3f);
    CHECK(glm::length(a.origin - b.origin) > 0.05f);  // the lens really moved the origin
    const glm::vec3 pa = a.origin + a.dir * ((-3.0f - a.origin.z) / a.dir.z);
    const glm::vec3 pb = b.origin + b.dir * ((-3.0f - b.origin.z) / b.dir.z);
    CHECK(glm::length(pa - pb) < 1e-5f);
}

TEST_CASE("camera: near_clip starts every ray on the plane that far along the view axis", "[render][camera]") {
    Camera c;
    c.position = {50.0f, 52.0f, 295.6f};
    c.look_at = {50.0f, 51.957388f, 294.6f};
    c.near_clip = 140.0f;
    const glm::vec3 forward = glm::normalize(c.look_at - c.position);
    for (const float aperture : {0.0f, 0.5f}) {
        c.aperture = aperture;
        const CameraModel cam(c, 64, 48);
        for (const auto& [x, y] : {std::pair{0.0f, 0.0f}, std::pair{32.0f, 24.0f}, std::pair{63.5f, 47.0f}}) {
            const collision::Ray r = cam.generate(x, y, 0.3f, 0.7f);
            CHECK(glm::dot(r.origin - c.position, forward) == Approx(140.0f).epsilon(1e-5));
            const glm::vec3 eye_side = r.origin - 140.0f / glm::dot(r.dir, forward) * r.dir;  // back to the lens plane
            CHECK(std::abs(glm::dot(eye_side - c.position, forward)) < 1e-3f);
        }
    }
}

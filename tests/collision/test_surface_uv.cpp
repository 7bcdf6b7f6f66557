// collision::surface_uv: the uv the curved shapes' intersect() no longer computes on every hit.
// Each parameterisation is checked by mapping the uv back to the surface point it names and
// comparing with the hit point (so a wrong axis, sign or scale fails), on seeded random rays.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "collision/intersect.hpp"
#include "collision/surface_uv.hpp"

using namespace collision;

namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
constexpr float kTol = 1e-4f;  // a few hundred roundings of unit-size values: atan2/acos/sqrt chains

template <class Shape, class Back>
int check_round_trip(const Shape& shape, Back&& back, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> n(0.0f, 1.0f);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 origin = 4.0f * glm::vec3(n(rng), n(rng), n(rng));
        const glm::vec3 target = 0.5f * glm::vec3(n(rng), n(rng), n(rng));
        RayHit h;
        if (!intersect(Ray{origin, target - origin}, shape, h)) continue;
        ++hits;
        const glm::vec2 uv = surface_uv(shape, h);
        INFO("hit " << h.point.x << " " << h.point.y << " " << h.point.z << " uv " << uv.x << " " << uv.y);
        REQUIRE(uv.x >= 0.0f);
        REQUIRE(uv.x <= 1.0f);
        REQUIRE(uv.y >= 0.0f);
        REQUIRE(uv.y <= 1.0f);
        REQUIRE(glm::length(back(uv, h) - h.point) <= kTol);
    }
    return hits;
}

// Point at angle fraction u around `axis` direction frame (x toward z for +y), radius r.
glm::vec3 around_y(float u, float r) { return r * glm::vec3(std::cos(kTwoPi * u), 0.0f, std::sin(kTwoPi * u)); }

}  // namespace

TEST_CASE("surface_uv: the intersectors leave uv at 0, surface_uv maps back to the hit point", "[intersect][uv]") {
    const Sphere sphere{{0.1f, -0.2f, 0.3f}, 1.2f};
    CHECK(check_round_trip(sphere, [&](glm::vec2 uv, const RayHit&) {
        const float phi = kTwoPi * uv.x, theta = std::numbers::pi_v<float> * uv.y;
        return sphere.center + sphere.radius * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                         std::sin(theta) * std::sin(phi));
    }, 1) > 200);

    const Ellipsoid ellipsoid{{0.0f, 0.2f, 0.0f}, {1.5f, 0.7f, 1.0f}};
    CHECK(check_round_trip(ellipsoid, [&](glm::vec2 uv, const RayHit&) {
        const float phi = kTwoPi * uv.x, theta = std::numbers::pi_v<float> * uv.y;
        return ellipsoid.center + ellipsoid.radii * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                              std::sin(theta) * std::sin(phi));
    }, 2) > 200);

    const Cylinder cylinder{{0.0f, 0.1f, 0.2f}, 0.9f, 1.6f};
    CHECK(check_round_trip(cylinder, [&](glm::vec2 uv, const RayHit& h) {
        const float ylo = cylinder.center.y - 0.5f * cylinder.height;
        if (h.normal.y != 0.0f)  // caps: (x, z) scaled into [0, 1]
            return glm::vec3(cylinder.center.x + (uv.x - 0.5f) * 2.0f * cylinder.radius, h.normal.y > 0 ? ylo + cylinder.height : ylo,
                             cylinder.center.z + (uv.y - 0.5f) * 2.0f * cylinder.radius);
        return glm::vec3(cylinder.center.x, ylo + uv.y * cylinder.height, cylinder.center.z) + around_y(uv.x, cylinder.radius);
    }, 3) > 200);

    const Capsule capsule{{0.0f, 0.0f, 0.1f}, 0.6f, 1.2f};
    CHECK(check_round_trip(capsule, [&](glm::vec2 uv, const RayHit& h) {
        // u is the angle of the normal around +y, v the height from the bottom pole.
        const float bottom = capsule.center.y - 0.5f * capsule.height - capsule.radius;
        const glm::vec3 across = glm::vec3(h.normal.x, 0.0f, h.normal.z);
        return glm::vec3(capsule.center.x, bottom + uv.y * (capsule.height + 2.0f * capsule.radius), capsule.center.z) +
               around_y(uv.x, glm::length(across) * capsule.radius);
    }, 4) > 200);

    const Disk disk{{0.2f, 0.0f, -0.1f}, {0.0f, 0.0f, 1.0f}, 1.3f};
    // v is the angle around the normal from a basis vector in the plane: measured from the
    // direction +x (probed), in the turning sense the +y probe shows.
    RayHit probe;
    probe.point = disk.center + glm::vec3(1.0f, 0.0f, 0.0f);
    const float v_x = surface_uv(disk, probe).y;
    probe.point = disk.center + glm::vec3(0.0f, 1.0f, 0.0f);
    const float quarter = surface_uv(disk, probe).y - v_x;
    const float turn = std::fabs(quarter - 0.25f) < kTol || std::fabs(quarter + 0.75f) < kTol ? 1.0f : -1.0f;
    CHECK(check_round_trip(disk, [&](glm::vec2 uv, const RayHit&) {
        const float phi = kTwoPi * turn * (uv.y - v_x);
        return disk.center + uv.x * disk.radius * glm::vec3(std::cos(phi), std::sin(phi), 0.0f);
    }, 5) > 100);

    RayHit h;
    REQUIRE(intersect(Ray{{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, sphere, h));
    CHECK(h.uv == glm::vec2(0.0f));
}

TEST_CASE("surface_uv: the oriented capsule's v runs along its axis, aligned ones match the Y capsule's u",
          "[intersect][uv]") {
    const OrientedCapsule c{{0.0f, -0.6f, 0.0f}, {0.0f, 0.6f, 0.0f}, 0.5f};
    std::mt19937 rng(6);
    std::normal_distribution<float> n(0.0f, 1.0f);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 origin = 4.0f * glm::vec3(n(rng), n(rng), n(rng));
        RayHit h;
        if (!intersect(Ray{origin, -origin}, c, h)) continue;
        ++hits;
        const glm::vec2 uv = surface_uv(c, h);
        // v = (distance along the axis from a, plus r) / (length + 2 r).
        CHECK(uv.y == Approx((h.point.y + 0.6f + 0.5f) / 2.2f).margin(kTol));
        REQUIRE(uv.x >= 0.0f);
        REQUIRE(uv.x <= 1.0f);
    }
    CHECK(hits > 100);
}

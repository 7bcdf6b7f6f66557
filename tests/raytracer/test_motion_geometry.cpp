// Motion (geometry/motion.hpp): poses between keys as pbrt-v4's animated transforms give them,
// exact at the keys, and boxes over the shutter (and per Embree time step) that hold the object
// at every time.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "raytracer/geometry/motion.hpp"
#include "raytracer/geometry/object_space.hpp"
#include "raytracer/scene/scene_transform.hpp"

using namespace sweeptrace;

namespace {

Transform key(const glm::dmat4& m) { return Transform::from_matrix(glm::mat4(m)); }

glm::dmat4 trs(const glm::dvec3& t, const glm::dvec3& axis, double degrees, const glm::dvec3& s) {
    return translation_matrix(t) * rotation_matrix(axis, degrees) * scale_matrix(s);
}

double max_difference(const glm::mat4& a, const glm::dmat4& b) {
    double d = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, std::fabs(double(a[c][r]) - b[c][r]));
    return d;
}

bool contains(const collision::Bounds3& outer, const collision::Bounds3& inner) {
    for (int a = 0; a < 3; ++a)
        if (!(outer.lo[a] <= inner.lo[a] && inner.hi[a] <= outer.hi[a])) return false;
    return true;
}

}  // namespace

TEST_CASE("motion: poses are the keys at their times and T, slerp(R), S between", "[motion]") {
    const glm::dvec3 axis(0.3, 1.0, -0.2);
    const Motion m = make_motion({key(trs({0, 0, 0}, axis, 0, {1, 1, 1})), key(trs({2, 0, 0}, axis, 60, {1, 2, 1})),
                                  key(trs({2, 4, 0}, axis, 150, {1, 2, 3}))});
    CHECK_FALSE(m.translation_only);
    // At the keys: the key's Transform itself, bit for bit.
    CHECK(pose_at(m, 0.0f).to_world == m.keys[0].to_world);
    CHECK(pose_at(m, 0.5f).to_world == m.keys[1].to_world);
    CHECK(pose_at(m, 1.0f).to_world == m.keys[2].to_world);
    CHECK(pose_at(m, 0.5f).to_object == m.keys[1].to_object);
    // Between: the rotation angle, translation and scale at the same fraction of the segment.
    for (double f : {0.1, 0.25, 0.5, 0.8}) {
        const double s = 0.5 + 0.5 * f;
        const glm::dmat4 expected = trs({2, 4 * f, 0}, axis, 60 + 90 * f, {1, 2, 1 + 2 * f});
        INFO("f = " << f);
        CHECK(max_difference(pose_at(m, float(s)).to_world, expected) < 1e-5);
        // to_object is the inverse of the pose's float to_world.
        const glm::dmat4 product = glm::dmat4(pose_at(m, float(s)).to_object) * glm::dmat4(pose_at(m, float(s)).to_world);
        CHECK(max_difference(glm::mat4(product), glm::dmat4(1.0)) < 1e-5);
    }
    // A segment whose keys are equal: its first key, bit for bit, at every time in it.
    const Motion rest = make_motion({m.keys[0], m.keys[0], m.keys[1]});
    CHECK(pose_at(rest, 0.3f).to_world == m.keys[0].to_world);
    CHECK(pose_at(rest, 0.3f).to_object == m.keys[0].to_object);
    // Outside the shutter: clamped.
    CHECK(pose_at(m, -1.0f).to_world == m.keys[0].to_world);
    CHECK(pose_at(m, 2.0f).to_world == m.keys[2].to_world);
}

TEST_CASE("motion: rotation takes the shorter arc, and translation-only motion keeps the linear part", "[motion]") {
    const glm::dvec3 y(0, 1, 0);
    // 350 degrees is -10: the pose halfway is at -5 degrees, not 175.
    const Motion m = make_motion({key(trs({0, 0, 0}, y, 0, {1, 1, 1})), key(trs({0, 0, 0}, y, 350, {1, 1, 1}))});
    CHECK(m.angles[0] == Approx(10.0 * M_PI / 180.0).epsilon(1e-5));  // from the float key matrices
    CHECK(max_difference(pose_at(m, 0.5f).to_world, rotation_matrix(y, -5)) < 1e-6);

    const Motion t = make_motion({key(trs({0, 0, 0}, y, 30, {2, 1, 1})), key(trs({4, 0, 2}, y, 30, {2, 1, 1}))});
    CHECK(t.translation_only);
    const Transform mid = pose_at(t, 0.25f);
    for (int c = 0; c < 3; ++c) CHECK(glm::vec3(mid.to_world[c]) == glm::vec3(t.keys[0].to_world[c]));
    CHECK(mid.to_world[3].x == 1.0f);
    CHECK(mid.to_world[3].z == 0.5f);
}

TEST_CASE("motion: the box over the shutter and the per-step boxes hold the object at every time", "[motion]") {
    const collision::Bounds3 box{{-0.5f, -0.2f, -1.0f}, {0.5f, 0.7f, 1.0f}};
    const glm::dvec3 axis(1.0, 2.0, 0.5);
    const std::vector<Motion> motions = {
        make_motion({key(trs({0, 0, 0}, axis, 0, {1, 1, 1})), key(trs({3, 1, 0}, axis, 0, {1, 1, 1}))}),
        make_motion({key(trs({0, 0, 0}, axis, 0, {1, 1, 1})), key(trs({0, 0, 0}, axis, 170, {1, 1, 1}))}),
        make_motion({key(trs({5, 0, 0}, axis, 20, {1, 1, 1})), key(trs({5, 2, 0}, axis, 100, {2, 0.5, 1})),
                     key(trs({4, 2, 1}, axis, 260, {1, 1, 3}))}),
    };
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (std::size_t i = 0; i < motions.size(); ++i) {
        const Motion& m = motions[i];
        const collision::Bounds3 whole = motion_world_bounds(m, box);
        const int steps = motion_time_steps(m);
        const std::vector<collision::Bounds3> step = motion_step_bounds(m, box, steps);
        REQUIRE(step.size() == std::size_t(steps));
        for (int n = 0; n < 2000; ++n) {
            const float s = n == 0 ? 0.0f : n == 1 ? 1.0f : u(rng);
            const collision::Bounds3 at = world_bounds(pose_at(m, s), box);
            INFO("motion " << i << ", s = " << s);
            REQUIRE(contains(whole, at));
            // Embree's reading: the box interpolated between the two steps around s.
            const float x = s * float(steps - 1);
            const int j = std::min(int(x), steps - 2);
            const float f = x - float(j);
            collision::Bounds3 lerp;
            lerp.lo = (1.0f - f) * step[j].lo + f * step[j + 1].lo;
            lerp.hi = (1.0f - f) * step[j].hi + f * step[j + 1].hi;
            // The interpolation's own rounding (a few ulps) is Embree's to pad; the test checks the
            // bound it interpolates between with that slack.
            const float slack = 1e-5f * (1.0f + glm::length(lerp.hi - lerp.lo));
            lerp.lo -= glm::vec3(slack);
            lerp.hi += glm::vec3(slack);
            REQUIRE(contains(lerp, at));
        }
    }
    // Pure translation: exactly the union of the ends (no growth).
    const collision::Bounds3 a = world_bounds(motions[0].keys[0], box), b = world_bounds(motions[0].keys[1], box);
    collision::Bounds3 both = a;
    both.extend(b);
    const collision::Bounds3 whole = motion_world_bounds(motions[0], box);
    CHECK(whole.lo == both.lo);
    CHECK(whole.hi == both.hi);
}

TEST_CASE("motion: a rotation's box is not much larger than the swept region", "[motion]") {
    // A box turning 90 degrees about its own centre's axis: the true reach is the circle of its
    // corner; the bound may exceed it only by the chord growth of 16 pieces and rounding.
    const collision::Bounds3 box{{-1.0f, -0.1f, -0.1f}, {1.0f, 0.1f, 0.1f}};
    const Motion m = make_motion({key(rotation_matrix({0, 0, 1}, 0)), key(rotation_matrix({0, 0, 1}, 90))});
    const collision::Bounds3 whole = motion_world_bounds(m, box);
    const float reach = std::sqrt(1.0f + 0.01f);
    CHECK(whole.hi.x <= reach * 1.01f);
    CHECK(whole.hi.y <= reach * 1.01f);
    CHECK(whole.hi.x >= 1.0f);
    CHECK(whole.hi.y >= 1.0f);
}

TEST_CASE("motion: fewer than 2 keys or a mirror is refused", "[motion]") {
    CHECK_THROWS_AS(make_motion({key(glm::dmat4(1.0))}), std::invalid_argument);
    CHECK_THROWS_AS(make_motion({key(glm::dmat4(1.0)), key(scale_matrix({-1, 1, 1}))}), std::invalid_argument);
}

// The portal (render/lights/portal.hpp) and the background as a light (render/lights/background_light.hpp):
// the portal's solid angle against the closed form, its directions uniform in that solid angle
// (chi-square over cells of the rectangle, each cell's solid angle by Van Oosterom and
// Strackee's triangle formula, independent of the sampler's), sample() and pdf() agreeing, and
// each background kind's density (with and without a portal, a map's mixture too) integrating to 1
// and being the one pdf() reports.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "environment_test_maps.hpp"
#include "raytracer/render/lights/background_light.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/lights/portal.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/sampling.hpp"

using namespace sweeptrace;

namespace {

constexpr double kPortalTestPi = 3.14159265358979323846;

// The solid angle of triangle (a, b, c) seen from the origin (Van Oosterom and Strackee 1983).
double portal_test_triangle_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double num = std::abs(glm::dot(a, glm::cross(b, c)));
    const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return 2.0 * std::atan2(num, den);
}

// The rectangle corner + [x0, x1] ex + [y0, y1] ey seen from p: two triangles.
double portal_test_cell_angle(const glm::dvec3& p, const glm::dvec3& corner, const glm::dvec3& ex, const glm::dvec3& ey,
                        double x0, double x1, double y0, double y1) {
    const glm::dvec3 a = corner + x0 * ex + y0 * ey - p, b = corner + x1 * ex + y0 * ey - p;
    const glm::dvec3 c = corner + x1 * ex + y1 * ey - p, d = corner + x0 * ex + y1 * ey - p;
    return portal_test_triangle_angle(a, b, c) + portal_test_triangle_angle(a, c, d);
}

// A 2 x 1 window in the plane z = 0 (corners round its edge), tilted points of view around it.
const std::array<glm::vec3, 4> kPortalTestWindow = {glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(2, 1, 0), glm::vec3(0, 1, 0)};

}  // namespace

TEST_CASE("portal: the solid angle is the closed form's, on the axis and off it", "[render][portal]") {
    const Portal portal(kPortalTestWindow);
    // On the axis through the centre at distance d: 4 asin(a b / sqrt((a^2 + 4 d^2)(b^2 + 4 d^2))).
    for (const double d : {0.01, 0.5, 3.0, 200.0}) {
        INFO("d = " << d);
        const double want = 4.0 * std::asin(2.0 / std::sqrt((4.0 + 4.0 * d * d) * (1.0 + 4.0 * d * d)));
        CHECK(portal.solid_angle(glm::vec3(1.0f, 0.5f, float(d))) == Approx(want).epsilon(1e-5));
        CHECK(portal.solid_angle(glm::vec3(1.0f, 0.5f, -float(d))) == Approx(want).epsilon(1e-5));  // either side
    }
    // Off the axis, against the triangle formula.
    const glm::dvec3 p(-0.7, 1.6, 0.45);
    const double want = portal_test_cell_angle(p, glm::dvec3(0.0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), 0.0, 2.0, 0.0, 1.0);
    CHECK(portal.solid_angle(glm::vec3(p)) == Approx(want).epsilon(1e-5));
    CHECK(portal.solid_angle(glm::vec3(5.0f, 3.0f, 0.0f)) == 0.0);  // in its plane: no solid angle
}

TEST_CASE("portal: directions are uniform in its solid angle (chi-square) and pdf() is sample()'s", "[render][portal]") {
    const Portal portal(kPortalTestWindow);
    for (const glm::dvec3 p : {glm::dvec3(0.3, -0.4, 0.8), glm::dvec3(1.0, 0.5, -0.05), glm::dvec3(-3.0, 2.0, 1.5)}) {
        INFO("p = " << p.x << " " << p.y << " " << p.z);
        constexpr int nx = 8, ny = 4, n = 200000;
        const double total = portal.solid_angle(glm::vec3(p));
        REQUIRE(total > 0.0);
        std::vector<int> hist(nx * ny, 0);
        Rng rng(11, 0, 0);
        int mismatched = 0;
        for (int s = 0; s < n; ++s) {
            glm::vec3 dir(0.0f);
            float pdf = 0.0f;
            REQUIRE(portal.sample(glm::vec3(p), rng.uniform(), rng.uniform(), dir, pdf));
            REQUIRE(glm::length(dir) == Approx(1.0f).epsilon(1e-5));
            CHECK(pdf == Approx(1.0 / total).epsilon(1e-5));
            // The ray meets the rectangle's plane inside it; pdf() agrees but on its very edge.
            const double t = -p.z / dir.z;
            REQUIRE(t > 0.0);
            const double x = p.x + t * dir.x, y = p.y + t * dir.y;
            if (portal.pdf(glm::vec3(p), dir) != pdf) ++mismatched;
            const int i = std::clamp(int(x / 2.0 * nx), 0, nx - 1), j = std::clamp(int(y * ny), 0, ny - 1);
            ++hist[static_cast<std::size_t>(j * nx + i)];
        }
        CHECK(mismatched <= n / 10000);  // rounding on the rectangle's edge only
        double chi2 = 0.0;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const double cell = portal_test_cell_angle(p, glm::dvec3(0.0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), 2.0 * i / nx,
                                                     2.0 * (i + 1) / nx, double(j) / ny, double(j + 1) / ny);
                const double e = cell / total * n;
                const double o = hist[static_cast<std::size_t>(j * nx + i)];
                chi2 += (o - e) * (o - e) / e;
            }
        const int dof = nx * ny - 1;
        CHECK(chi2 < dof + 6.0 * std::sqrt(2.0 * dof));  // ~ p 1e-6 for 31 degrees of freedom
    }
}

TEST_CASE("portal: pdf() is zero for directions that miss the rectangle", "[render][portal]") {
    const Portal portal(kPortalTestWindow);
    const glm::vec3 p(1.0f, 0.5f, 1.0f);
    CHECK(portal.pdf(p, glm::vec3(0, 0, -1)) > 0.0f);   // through its centre
    CHECK(portal.pdf(p, glm::vec3(0, 0, 1)) == 0.0f);   // away from its plane
    CHECK(portal.pdf(p, glm::normalize(glm::vec3(3, 0, -1))) == 0.0f);  // the plane beyond its edge
}

namespace {

// The integral of a background light's NEE density over the sphere from p, by stratified
// uniform directions (the density may be 0 on most of the sphere: a portal's), and the largest
// relative difference between a sample's reported density and pdf() of its direction.
struct BackgroundDensityCheck {
    double integral = 0.0;
    double worst = 0.0;
};
BackgroundDensityCheck check_background_density(const BackgroundLight& light, const glm::vec3& p) {
    BackgroundDensityCheck c;
    constexpr int m = 600;  // m x m strata
    double sum = 0.0;
    Rng rng(3, 0, 0);
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const glm::vec3 w = uniform_sphere((i + rng.uniform()) / m, (j + rng.uniform()) / m);
            sum += light.pdf(p, w);
        }
    c.integral = sum * 4.0 * kPortalTestPi / (double(m) * m);
    for (int s = 0; s < 20000; ++s) {
        glm::vec3 dir(0.0f), le(0.0f);
        float pdf = 0.0f;
        if (!light.sample(p, rng.uniform(), rng.uniform(), dir, pdf, le)) continue;
        const double q = light.pdf(p, dir);
        if (q > 0.0) c.worst = std::max(c.worst, std::abs(pdf - q) / q);
        else c.worst = 1.0;  // edge rounding is counted as a full mismatch: there must be none here
        REQUIRE(le == light.radiance(dir));
    }
    return c;
}

}  // namespace

TEST_CASE("background light: every kind's density integrates to 1 and is the one pdf() reports, with and without a portal",
          "[render][portal][background]") {
    Background colour;
    colour.kind = Background::Kind::Constant;
    colour.color = glm::vec3(2.0f);
    Background sky;
    sky.kind = Background::Kind::Sky;
    sky.horizon = glm::vec3(1.0f, 0.9f, 0.8f);
    sky.zenith = glm::vec3(0.2f, 0.3f, 0.9f);
    Background map;
    map.kind = Background::Kind::Environment;
    map.environment = testing::environment_test_map(16, 8);
    const glm::vec3 p(0.4f, 0.7f, 1.3f);
    for (const bool portal : {false, true}) {
        for (Background* bg : {&colour, &sky, &map}) {
            bg->has_portal = portal;
            bg->portal = kPortalTestWindow;
            INFO("kind " << int(bg->kind) << (portal ? " with a portal" : ""));
            const BackgroundLight light(*bg);
            REQUIRE(light.emits());
            const BackgroundDensityCheck c = check_background_density(light, p);
            CHECK(c.integral == Approx(1.0).epsilon(0.02));
            CHECK(c.worst < 1e-3);
            if (portal && bg->kind != Background::Kind::Environment) {
                // Only through the window: its density is 1 / Omega there, 0 elsewhere.
                const double omega = Portal(kPortalTestWindow).solid_angle(p);
                CHECK(light.pdf(p, glm::normalize(glm::vec3(1.0f, 0.5f, 0.0f) - p)) == Approx(1.0 / omega).epsilon(1e-5));
                CHECK(light.pdf(p, glm::vec3(0, 1, 0)) == 0.0f);
            }
        }
    }
}

TEST_CASE("background light: a map is a light, a colour or the sky only with a portal, a black one never",
          "[render][background]") {
    Scene scene;
    scene.background.kind = Background::Kind::Constant;
    scene.background.color = glm::vec3(0.5f, 0.0f, 0.0f);
    CHECK_FALSE(LightSet(scene).background_is_light());  // left to BSDF sampling (scene_lights.cpp)
    scene.background.has_portal = true;
    scene.background.portal = kPortalTestWindow;
    const LightSet colour(scene);
    CHECK(colour.background_is_light());
    CHECK(colour.light_count() == 1);
    const glm::vec3 p(1.0f, 0.5f, 2.0f);
    LightSample ls;
    REQUIRE(colour.sample(p, LightSet::kNoObject, 0.5f, 0.5f, 0.3f, 0.6f, ls));
    CHECK(ls.at_infinity);
    CHECK(ls.pdf == Approx(1.0 / Portal(kPortalTestWindow).solid_angle(p)));
    CHECK(ls.radiance == glm::vec3(0.5f, 0.0f, 0.0f));
    scene.background.kind = Background::Kind::Sky;
    CHECK(LightSet(scene).background_is_light());
    scene.background.kind = Background::Kind::Constant;
    scene.background.color = glm::vec3(0.0f);
    CHECK_FALSE(LightSet(scene).background_is_light());
}

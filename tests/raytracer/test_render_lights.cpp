// Light sampling: every shape's sampler produces the density pdf() reports for the same point,
// and the densities integrate to the true area (or solid angle).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "raytracer/render/guiding/guiding_quadtree.hpp"
#include "raytracer/render/lights/lights.hpp"
#include "raytracer/render/sampling/random.hpp"
#include "raytracer/render/sampling/sampling.hpp"
#include "render_test_scenes.hpp"
#include "render_test_stats.hpp"

using namespace sweeptrace;
using sweeptrace::test::Estimate;
using sweeptrace::test::z_bound;

namespace {

Scene single_light(const Shape& shape, const glm::mat4& m, glm::vec3 emission = glm::vec3(1.0f)) {
    Scene s;
    Material mat;
    mat.type = Material::Type::Emissive;
    mat.emission = emission;
    s.materials.push_back(mat);
    Object o;
    o.shape = shape;
    o.transform = Transform::from_matrix(m);
    s.objects.push_back(o);
    return s;
}

const glm::mat4 kTilted = glm::rotate(glm::translate(glm::mat4(1.0f), {0.3f, -0.2f, 0.5f}), 0.7f,
                                      glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));

// From shading point p: E[1/p_area] over light samples (front and back alike) is the light's
// world area; pdf(p, hit) at each sampled point equals the density it was sampled with.
double sampled_area(const Scene& scene, const glm::vec3& p, std::uint64_t seed, Estimate& est) {
    Scene both = scene;
    both.materials[0].two_sided_emission = true;  // so back-facing samples are returned too
    const LightSet lights(both);
    REQUIRE(lights.size() == 1);
    Rng rng(seed, 0, 0);
    for (int i = 0; i < 100000; ++i) {
        LightSample ls;
        const bool ok = lights.sample(p, LightSet::kNoObject, rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform(), ls);
        if (!ok) {
            est.add(0.0);
            continue;
        }
        SurfaceHit h;
        h.point = ls.point;
        h.normal = ls.normal;
        h.object = 0;
        const float cos_l = std::abs(glm::dot(ls.normal, ls.wi));
        // Same point, same normal; pdf() recomputes the light's cosine as dot(n, w) / |w| instead
        // of dot(n, w / |w|): a few ulps apart, relatively 1/cos_l times more in the cosine.
        REQUIRE(lights.pdf(p, LightSet::kNoObject, h) == Approx(ls.pdf).epsilon(1e-6 + 1e-6 / cos_l));
        est.add(double(ls.distance) * ls.distance / (double(ls.pdf) * cos_l));
    }
    return est.mean;
}

double spheroid_area(double a, double c) {  // prolate, c > a
    const double e = std::sqrt(1.0 - a * a / (c * c));
    return 2.0 * M_PI * a * a * (1.0 + c / (a * e) * std::asin(e));
}

}  // namespace

TEST_CASE("lights: area sampling of every shape integrates to its world area", "[render][lights]") {
    struct Case {
        std::string name;
        Shape shape;
        glm::mat4 m;
        double area;
    };
    const glm::mat4 stretch_y = glm::scale(glm::mat4(1.0f), {1.0f, 2.0f, 1.0f});
    const glm::mat4 scaled2 = glm::scale(kTilted, glm::vec3(2.0f));
    const Case cases[] = {
        {"quad", collision::Quad{{0, 0, 0}, {1, 0, 0}, {0.5f, 0, 2}}, kTilted, 2.0},
        {"sheared quad", collision::Quad{{0, 0, 0}, {1, 0, 0}, {0, 0, 2}}, glm::scale(kTilted, {1.0f, 3.0f, 0.5f}), 1.0},
        {"disk", collision::Disk{{1, 0, 0}, glm::normalize(glm::vec3(1, 1, 0)), 0.5f}, kTilted, M_PI * 0.25},
        {"stretched disk", collision::Disk{{0, 0, 0}, {0, 0, 1}, 1.0f}, glm::scale(kTilted, {3.0f, 1.0f, 1.0f}), 3.0 * M_PI},
        {"triangle", collision::Triangle{{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}, kTilted, 3.0},
        {"stretched sphere", collision::Sphere{{0, 0, 0}, 1.0f}, stretch_y, spheroid_area(1.0, 2.0)},
        {"ellipsoid", collision::Ellipsoid{{0.5f, 0, 0}, {1.0f, 2.0f, 1.0f}}, kTilted, spheroid_area(1.0, 2.0)},
        {"box", collision::Aabb{{0, 0, 0}, {1, 2, 3}}, glm::scale(kTilted, {2.0f, 1.0f, 1.0f}),
         2.0 * (2 * 2 + 2 * 3 + 2 * 3)},
        {"cylinder", collision::Cylinder{{0, 0, 0}, 0.5f, 2.0f}, scaled2, 4.0 * 2.0 * M_PI * 0.5 * (0.5 + 2.0)},
        {"capsule", collision::Capsule{{0, 1, 0}, 0.5f, 1.0f}, kTilted, 2.0 * M_PI * 0.5 * 1.0 + 4.0 * M_PI * 0.25},
    };
    std::uint64_t seed = 100;
    for (const Case& c : cases) {
        INFO(c.name);
        Estimate est;
        sampled_area(single_light(c.shape, c.m), {5.0f, 4.0f, 3.0f}, ++seed, est);
        CHECK(std::abs(est.mean - c.area) < z_bound(20) * est.standard_error() + 1e-6 * c.area);
        CHECK(est.standard_error() < 0.05 * c.area);  // the test has power
    }
}

TEST_CASE("lights: a mesh light is sampled uniformly over its transformed surface", "[render][lights]") {
    Scene s = single_light(MeshInstance{0}, glm::scale(kTilted, {1.0f, 2.0f, 1.0f}));
    Mesh mesh;
    // Two triangles of areas 0.5 and 2 (before the y-stretch, which doubles both: they lie in z=0
    // spanning x and y).
    mesh.triangles.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 0, 0}, {5, 0, 0}, {3, 2, 0}};
    mesh.triangles.indices = {{0, 1, 2}, {3, 4, 5}};
    s.meshes.push_back(mesh);
    Estimate est;
    sampled_area(s, {5.0f, 4.0f, 3.0f}, 7, est);
    CHECK(std::abs(est.mean - 5.0) < z_bound(1) * est.standard_error() + 1e-6);
}

// A sphere of radius 0.4 scaled by 1.5 under a tilted transform, sampled in its cone from
// points along one direction at distances 1, 3 and 300 from its centre, `n` samples each
// (with `guide` when given). Every sample must be a point of the sphere's visible side inside
// the cone; `each(ls, hit, p)` checks more, and the estimate of E[1 / pdf], which is the cone's
// solid angle for any density the sampler truly draws with, is checked per distance.
template <class Each>
void check_cone_samples(int n, std::uint64_t seed, const DirectionalQuadtree* guide, Each each) {
    const glm::mat4 m = glm::scale(kTilted, glm::vec3(1.5f));
    const Scene scene = single_light(collision::Sphere{{1, 0, 0}, 0.4f}, m);
    const LightSet lights(scene);  // keeps pointers into the scene
    const glm::vec3 c = glm::vec3(m * glm::vec4(1, 0, 0, 1));
    const float r = 0.6f;
    for (float dist : {1.0f, 3.0f, 300.0f}) {
        const glm::vec3 p = c + dist * glm::normalize(glm::vec3(1.0f, 0.5f, -0.2f));
        Rng rng(9, seed, 0);
        Estimate solid;
        const double cos_max = std::sqrt(1.0 - (double)r * r / ((double)dist * dist));
        for (int i = 0; i < n; ++i) {
            LightSample ls;
            REQUIRE(lights.sample(p, LightSet::kNoObject, rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform(), ls,
                                  guide));
            // On the sphere to float accuracy of its coordinates (gamma(5) (|c| + r) each).
            REQUIRE(std::abs(glm::length(ls.point - c) - r) < 1e-5f * (glm::length(c) + r));
            REQUIRE(glm::dot(ls.normal, p - ls.point) >= -1e-5f * dist);  // the visible side
            // Inside the cone: the direction's angle to the centre is at most theta_max.
            REQUIRE(glm::dot(ls.wi, glm::normalize(c - p)) >= cos_max - 1e-6);
            SurfaceHit h;
            h.point = ls.point;
            h.normal = ls.normal;
            each(lights, ls, h, p);
            solid.add(1.0 / ls.pdf);
        }
        const double truth = 2.0 * M_PI * (1.0 - cos_max);
        // Unguided, 1/pdf is the same for every sample, so the mean must hit the solid angle to
        // float accuracy; guided it varies, and the mean is judged against its standard error.
        if (guide == nullptr) CHECK(solid.mean == Approx(truth).epsilon(1e-4));
        else CHECK(std::abs(solid.mean - truth) < z_bound(6) * solid.standard_error() + 1e-4 * truth);
    }
}

TEST_CASE("lights: a similar-transformed sphere is sampled in its cone, points visible, mean 1/pdf = solid angle", "[render][lights]") {
    check_cone_samples(20000, 0, nullptr, [](const LightSet& lights, const LightSample& ls, const SurfaceHit& h, const glm::vec3& p) {
        REQUIRE(lights.pdf(p, LightSet::kNoObject, h) == Approx(ls.pdf).epsilon(1e-6));
    });
}

TEST_CASE("lights: a guided cone samples the guide's mixture, pdf() maps a found point back to its density, mean 1/pdf = solid angle", "[render][lights][guiding]") {
    // A guide whose energy sits in [0, 0.125) x [0.25, 0.375) of the square: a narrow band of
    // angles around the cone's axis, one eighth of its azimuths.
    DirectionalQuadtree coarse;
    Rng fill(4, 4, 4);
    const auto record = [&fill](DirectionalQuadtree& t) {
        for (int i = 0; i < 4000; ++i) t.record_square({0.125f * fill.uniform(), 0.25f + 0.125f * fill.uniform()}, 1.0f);
    };
    record(coarse);
    DirectionalQuadtree guide = coarse.refined(0.01, 20);
    record(guide);
    guide.freeze();
    const int n = 40000;
    int inside = 0, density_differs = 0;
    check_cone_samples(n, 1, &guide, [&](const LightSet& lights, const LightSample& ls, const SurfaceHit& h, const glm::vec3& p) {
        REQUIRE(ls.on_square);
        inside += ls.square.x < 0.125f && ls.square.y >= 0.25f && ls.square.y < 0.375f;
        // The same density from the point alone; only a point within float error of a cell
        // edge of the guide may read its neighbour's (the map back is not exact).
        const float back = lights.pdf(p, LightSet::kNoObject, h, &guide);
        if (!(std::abs(back - ls.pdf) <= 1e-4f * ls.pdf)) ++density_differs;
    });
    CHECK(density_differs <= 3 * n / 500);
    // Three quarters from the guide, all of whose mass is in its band: at least 0.7 there.
    CHECK(inside > 3 * 0.7 * n);
}

TEST_CASE("lights: selection follows power, and pdf() of a non-light is zero", "[render][lights]") {
    Scene s;
    Material dim, bright, plain;
    dim.emission = glm::vec3(1.0f);
    bright.emission = glm::vec3(3.0f);
    s.materials = {dim, bright, plain};
    const auto add = [&](const Shape& shape, std::uint32_t mat) {
        Object o;
        o.shape = shape;
        o.material = mat;
        s.objects.push_back(o);
    };
    add(collision::Quad{{0, 5, 0}, {1, 0, 0}, {0, 0, 1}}, 0);   // power 1 x area 1, facing down
    add(collision::Quad{{3, 5, 0}, {1, 0, 0}, {0, 0, 2}}, 1);   // power 3 x area 2
    add(collision::Sphere{{0, 0, 0}, 1.0f}, 2);                 // not a light
    const LightSet lights(s);
    REQUIRE(lights.size() == 2);
    CHECK(lights.selection_probability(0) == Approx(1.0f / 7.0f));
    CHECK(lights.selection_probability(1) == Approx(6.0f / 7.0f));
    CHECK(lights.selection_probability(2) == 0.0f);
    Rng rng(1, 0, 0);
    Estimate picked_first;
    for (int i = 0; i < 20000; ++i) {
        LightSample ls;
        REQUIRE(lights.sample({0.5f, 0, 0.5f}, LightSet::kNoObject, rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform(), ls));
        picked_first.add(ls.point.x < 2.0f ? 1.0 : 0.0);
    }
    CHECK(std::abs(picked_first.mean - 1.0 / 7.0) < z_bound(1) * picked_first.standard_error());
    SurfaceHit h;
    h.object = 2;
    h.point = {0, 1, 0};
    h.normal = {0, 1, 0};
    CHECK(lights.pdf({0, 3, 0}, LightSet::kNoObject, h) == 0.0f);
}

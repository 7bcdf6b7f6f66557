// Closed forms with the scene's "lights" (point, spot, directional): a diffuse plane under a
// point and a spot light (irradiance I cos(theta) / d^2), and the penumbra of a half-plane under
// a sun with an angular diameter (the cone integral, reduced to one dimension and evaluated in
// double), by both estimators and both accelerators; and the image is the same bit for bit at
// any thread count.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include <glm/geometric.hpp>

#include "convergence_harness.hpp"
#include "raytracer/render/sampling/sampling.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

constexpr double kPiD = 3.14159265358979323846;

// The camera ray through film position (fx, fy) of a size x size image: render/camera.hpp's
// model, in double.
struct DoubleCamera {
    glm::dvec3 origin, forward, right, up;
    double half;
    int size;
    explicit DoubleCamera(const Scene& s) : size(s.film.width) {
        const Camera& c = s.camera;
        origin = glm::dvec3(c.position);
        forward = glm::normalize(glm::dvec3(c.look_at - c.position));
        right = glm::normalize(glm::cross(forward, glm::dvec3(c.up)));
        up = glm::cross(right, forward);
        half = std::tan(0.5 * glm::radians(static_cast<double>(c.vfov_degrees)));
    }
    glm::dvec3 dir(double fx, double fy) const {
        return glm::normalize(forward + (2.0 * fx / size - 1.0) * half * right + (1.0 - 2.0 * fy / size) * half * up);
    }
};

// Per pixel, the mean over its area (the renderer jitters uniformly within it) of `value` by a
// sub x sub midpoint rule. `value` also returns which piece of the image the sample falls on; a
// pixel whose samples fall on different pieces (an edge the midpoint rule would only estimate)
// is masked out.
Image pixel_means(const Scene& s, int sub, std::vector<std::uint8_t>& mask,
                  const std::function<int(const glm::dvec3& dir, double& v)>& value) {
    const DoubleCamera cam(s);
    Image truth(cam.size, cam.size);
    mask.assign(truth.pixels.size(), 1);
    for (int y = 0; y < cam.size; ++y)
        for (int x = 0; x < cam.size; ++x) {
            double sum = 0.0;
            int piece = 0;
            for (int j = 0; j < sub; ++j)
                for (int i = 0; i < sub; ++i) {
                    double v = 0.0;
                    const int k = value(cam.dir(x + (i + 0.5) / sub, y + (j + 0.5) / sub), v);
                    if (i + j == 0) piece = k;
                    if (k != piece) mask[y * cam.size + x] = 0;
                    sum += v;
                }
            truth.at(x, y) = glm::vec3(static_cast<float>(sum / (sub * sub)));
        }
    return truth;
}

Scene plane_seen_from_above(int size, float rho) {
    Scene scene = empty_scene(size, size);
    scene.camera.position = {0.0f, 4.0f, 0.0f};
    scene.camera.look_at = glm::vec3(0.0f);
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.vfov_degrees = 60.0f;
    add_object(scene, collision::Quad{{-50.0f, 0.0f, -50.0f}, {0.0f, 0.0f, 100.0f}, {100.0f, 0.0f, 0.0f}},
               add_material(scene, diffuse(rho)), glm::mat4(1.0f), "plane");
    return scene;
}

double smoothstep_falloff(double cos_t, double cos_cone, double cos_start) {
    if (cos_t >= cos_start) return 1.0;
    if (cos_t <= cos_cone) return 0.0;
    const double t = (cos_t - cos_cone) / (cos_start - cos_cone);
    return t * t * (3.0 - 2.0 * t);
}

// A point (or spot, pointing straight down) light of intensity I at height h over the plane:
// a plane point at distance d reads rho / pi * I falloff h / d^3.
void check_delta_light(SceneLight light, double cos_cone, double cos_start) {
    constexpr int size = 48, spp = 16;
    const float rho = 0.8f, h = 1.0f;
    Scene scene = plane_seen_from_above(size, rho);
    light.position = {0.0f, h, 0.0f};
    light.intensity = glm::vec3(2.0f);
    scene.lights.push_back(light);
    std::vector<std::uint8_t> mask;
    const Image truth = pixel_means(scene, 16, mask, [&](const glm::dvec3& dir, double& v) {
        const glm::dvec3 p = glm::dvec3(scene.camera.position) + (scene.camera.position.y / -dir.y) * dir;
        const double d = glm::length(glm::dvec3(light.position) - p);
        v = rho / kPiD * 2.0 * smoothstep_falloff(h / d, cos_cone, cos_start) * h / (d * d * d);
        return 0;
    });
    // Deterministic allowance: a handful of float roundings of I / d^2, cos and the BSDF.
    for (AccelKind accel : {AccelKind::Bvh, AccelKind::Embree}) {
        const RenderResult r = render_with(scene, accel, spp, 4, 3);
        const BlockTestResult t = test_against_truth(truth, r, 4, 1e-5, &mask);
        INFO((accel == AccelKind::Bvh ? "bvh: " : "embree: ") << t.summary());
        CHECK(t.pass());
        CHECK(t.blocks_tested == (size / 4) * (size / 4));
    }
}

}  // namespace

TEST_CASE("point light over a diffuse plane: pixels read rho/pi I cos(theta) / d^2", "[convergence][lights]") {
    SceneLight point;
    point.type = SceneLight::Type::Point;
    check_delta_light(point, -2.0, -2.0);
}

TEST_CASE("spot light over a diffuse plane: the same times pbrt's smoothstep falloff", "[convergence][lights]") {
    SceneLight spot;
    spot.type = SceneLight::Type::Spot;
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.cos_cone = std::cos(glm::radians(40.0f));
    spot.cos_falloff_start = std::cos(glm::radians(20.0f));
    check_delta_light(spot, spot.cos_cone, spot.cos_falloff_start);
}

namespace {

// Irradiance at receiver point x (plane y = 0) from a sun straight overhead of radiance L and
// half-angle alpha, with a black half-plane occluder at height H over x < 0. In polar angle
// theta about +y and azimuth phi, a direction is unoccluded iff x + H tan(theta) cos(phi) > 0,
// so per theta the visible azimuths measure 2 acos(-x / (H tan theta)) (clamped), and
//   E(x) = L int_0^alpha cos(theta) sin(theta) 2 acos(clamp(-x / (H tan theta))) dtheta,
// by a 400-point midpoint rule (the integrand is continuous, with kinks where the clamp
// starts: error below 1e-6 relative); outside the penumbra it is pi L sin^2(alpha) or 0.
double penumbra_irradiance(double x, double L, double alpha, double H) {
    const double reach = H * std::tan(alpha);  // the penumbra's half-width
    if (x >= reach) return L * kPiD * std::sin(alpha) * std::sin(alpha);
    if (x <= -reach) return 0.0;
    constexpr int n = 400;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double th = (i + 0.5) * alpha / n;
        const double c = std::clamp(-x / (H * std::tan(th)), -1.0, 1.0);
        sum += std::cos(th) * std::sin(th) * 2.0 * std::acos(c);
    }
    return L * sum * alpha / n;
}

}  // namespace

TEST_CASE("sun with an angular diameter: the penumbra of a half-plane matches the cone integral, NEE+MIS and BSDF only",
          "[convergence][lights]") {
    constexpr int size = 32;
    const float rho = 0.8f, H = 1.0f, E = 3.0f;
    const double alpha = glm::radians(10.0);
    Scene scene = empty_scene(size, size);
    scene.camera.position = {0.15f, 3.0f, 0.0f};
    scene.camera.look_at = {0.15f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, 1.0f};
    scene.camera.vfov_degrees = 12.0f;
    add_object(scene, collision::Quad{{-50.0f, 0.0f, -50.0f}, {0.0f, 0.0f, 100.0f}, {100.0f, 0.0f, 0.0f}},
               add_material(scene, diffuse(rho)), glm::mat4(1.0f), "receiver");
    // Black both ways: it reflects neither the sun to the camera nor the receiver's light back.
    add_object(scene, collision::Quad{{-50.0f, H, -50.0f}, {0.0f, 0.0f, 100.0f}, {50.0f, 0.0f, 0.0f}},
               add_material(scene, diffuse(0.0f)), glm::mat4(1.0f), "occluder");
    SceneLight sun;
    sun.type = SceneLight::Type::Directional;
    sun.direction = {0.0f, -1.0f, 0.0f};
    sun.irradiance = glm::vec3(E);
    sun.half_angle = static_cast<float>(alpha);
    scene.lights.push_back(sun);
    const double L = E / (kPiD * std::sin(alpha) * std::sin(alpha));

    std::vector<std::uint8_t> mask;
    const Image truth = pixel_means(scene, 16, mask, [&](const glm::dvec3& dir, double& v) {
        const glm::dvec3 o(scene.camera.position);
        const bool hits_occluder = o.x + (o.y - H) / -dir.y * dir.x < 0.0;
        const glm::dvec3 p = o + (o.y / -dir.y) * dir;
        v = hits_occluder ? 0.0 : rho / kPiD * penumbra_irradiance(p.x, L, alpha, H);
        return hits_occluder ? 1 : 0;
    });
    // The view spans the receiver x in [-0.16, 0.46]: the whole penumbra (|x| < H tan(alpha)
    // = 0.176) that the edge (seen at x = -0.075) does not hide, and full sun beyond.
    for (AccelKind accel : {AccelKind::Bvh, AccelKind::Embree})
        for (Sampling sampling : {Sampling::NeeMis, Sampling::BsdfOnly}) {
            const bool nee = sampling == Sampling::NeeMis;
            const int spp = nee ? 64 : 256;
            const RenderResult r = render_with(scene, accel, spp, 3, nee ? 5 : 6, sampling);
            // Occlusion is a rare event at the penumbra's ends: a pixel whose samples all missed
            // it estimates its own variance near 0. So the test also uses the variance a correct
            // render must have (Var_null, see image/diff.hpp), a lower bound from the pixel's
            // visible fraction v = truth / full alone: NEE samples the cone and reads full or 0,
            // variance full^2 v (1 - v); a BSDF sample finds the sun with probability
            // q = v full / (rho L) and reads rho L, variance (rho L)^2 q (1 - q).
            const double full = rho / kPiD * E;
            Image null_variance(size, size);
            for (std::size_t i = 0; i < truth.pixels.size(); ++i) {
                const double v = std::clamp(truth.pixels[i].r / full, 0.0, 1.0);
                const double q = v * full / (rho * L);
                const double var = nee ? full * full * v * (1.0 - v) : rho * L * rho * L * q * (1.0 - q);
                null_variance.pixels[i] = glm::vec3(static_cast<float>(var / spp));
            }
            BlockTestOptions options;
            options.block = 4;
            options.golden_is_8bit = false;
            options.relative_tolerance = 1e-5;
            options.mask = &mask;
            options.null_variance = &null_variance;
            const BlockTestResult t = block_test(truth, r.image, r.variance, options);
            INFO((accel == AccelKind::Bvh ? "bvh" : "embree") << (nee ? ", NEE+MIS: " : ", BSDF only: ") << t.summary());
            CHECK(t.pass());
            CHECK(t.blocks_tested > 40);
        }
}

TEST_CASE("scene lights, environment, Mitchell filter, texture: the image is identical bit for bit at 1 and 3 threads",
          "[render][determinism][lights]") {
    Scene scene = plane_seen_from_above(37, 0.7f);
    scene.film.filter.type = FilterSpec::Type::Mitchell;  // negative weights and film offsets
    scene.film.filter.radius = 2.0f;
    auto map = std::make_shared<Image>(8, 4);
    for (std::size_t i = 0; i < map->pixels.size(); ++i) map->pixels[i] = glm::vec3(0.1f * static_cast<float>(i % 5));
    scene.background.kind = Background::Kind::Environment;
    scene.background.environment = map;
    scene.textures.push_back(Texture{});  // the default checker
    scene.materials[0].albedo_texture = 0;
    for (SceneLight::Type type : {SceneLight::Type::Point, SceneLight::Type::Spot, SceneLight::Type::Directional}) {
        SceneLight l;
        l.type = type;
        l.position = {0.3f, 1.0f, -0.2f};
        l.intensity = glm::vec3(1.0f, 2.0f, 3.0f);
        l.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
        l.cos_cone = 0.8f;
        l.cos_falloff_start = 0.9f;
        l.irradiance = glm::vec3(0.5f);
        l.half_angle = 0.1f;
        scene.lights.push_back(l);
    }
    add_object(scene, collision::Sphere{{0.0f, 0.4f, 0.0f}, 0.3f}, add_material(scene, diffuse(0.5f)), glm::mat4(1.0f),
               "ball");
    const auto accel = make_accel(AccelKind::Bvh, scene);
    const auto [one, three] = render_on_1_and_3_threads(scene, *accel);
    CHECK(same_bits(one.image, three.image));
    CHECK(luminance(one.image.at(18, 18)) > 0.0f);
}

// The thin lens against the circle of confusion's closed form. A lens of diameter A (the scene's
// "aperture") focused at distance f along the view axis: the rays through one film point leave
// the lens disk (radius A/2) and meet at that point's image on the focus plane, so on the plane
// at depth d they cross a disk of radius (A/2) |d - f| / f around the pinhole ray's point
// (similar triangles: the lens offset l moves the crossing by l (1 - d/f)). Seen from the film,
// a point at depth d blurs into a disk of radius (A/2) |d - f| / (f d) in image-plane units (the
// plane at distance 1). Both are checked here, the first on the camera's rays, the second on a
// render of a small bright sphere; a lens taking "aperture" as its radius would read twice these.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "convergence_harness.hpp"
#include "raytracer/render/camera.hpp"
#include "raytracer/render/sampling/random.hpp"

using namespace sweeptrace;
using namespace sweeptrace::testing;

namespace {

Camera lens_camera(float aperture, float focus) {
    Camera c;
    c.position = {0.0f, 0.0f, 0.0f};
    c.look_at = {0.0f, 0.0f, -10.0f};  // the focus distance is given, not taken from look_at
    c.vfov_degrees = 30.0f;
    c.aperture = aperture;
    c.focus_distance = focus;
    return c;
}

// Where a ray crosses the plane at depth d along the view axis (-z here).
glm::vec3 at_depth(const collision::Ray& r, float d) { return r.origin + r.dir * ((-d - r.origin.z) / r.dir.z); }

}  // namespace

TEST_CASE("thin lens: rays through one film point spread over a disk of radius (A/2)|d - f|/f at depth d", "[render][camera][lens]") {
    const float aperture = 0.4f, f = 2.0f;
    const CameraModel cam(lens_camera(aperture, f), 96, 96);
    Rng rng(3, 0, 0);
    for (const auto& [x, y] : {std::pair{48.0f, 48.0f}, std::pair{3.0f, 90.0f}})
        for (float d : {0.5f, 1.0f, 2.0f, 4.0f, 9.0f}) {
            // The pinhole ray's crossing: the lens sample at the disk's centre.
            const glm::vec3 centre = at_depth(cam.generate(x, y, 0.5f, 0.5f), d);
            double widest = 0.0;
            for (int i = 0; i < 4000; ++i) {
                // Half the samples on the lens's rim (u1 at the square's edge maps to the circle).
                const float u1 = i % 2 ? rng.uniform() : 1.0f - 1e-7f * rng.uniform();
                const glm::vec3 p = at_depth(cam.generate(x, y, u1, rng.uniform()), d);
                widest = std::max(widest, static_cast<double>(glm::length(p - centre)));
            }
            const double expected = 0.5 * aperture * std::abs(d - f) / f;
            INFO("film (" << x << ", " << y << ") depth " << d << ": widest " << widest << ", closed form " << expected);
            // Float error of the crossing: a few ulps of |p| (< 10) times the ray count's spread.
            CHECK(std::abs(widest - expected) <= 1e-4 * expected + 2e-5);
        }
}

TEST_CASE("thin lens: focus_distance is a plane along the view axis, not a distance along each ray", "[render][camera][lens]") {
    // Off axis (a film corner, ~20 degrees out) the rays of one film point meet on the plane at
    // depth f, where the pinhole ray has travelled f / cos > f; on the sphere of radius f they
    // do not meet.
    const float f = 3.0f;
    const CameraModel cam(lens_camera(0.5f, f), 96, 96);
    const float u[][2] = {{0.1f, 0.9f}, {0.8f, 0.3f}, {0.999f, 0.5f}, {0.5f, 0.001f}};
    const glm::vec3 on_plane = at_depth(cam.generate(0.0f, 0.0f, u[0][0], u[0][1]), f);
    double plane_spread = 0.0, sphere_spread = 0.0;
    const collision::Ray pin = cam.generate(0.0f, 0.0f, 0.5f, 0.5f);
    const glm::vec3 on_sphere = pin.origin + f * pin.dir;
    for (const auto& s : u) {
        const collision::Ray r = cam.generate(0.0f, 0.0f, s[0], s[1]);
        plane_spread = std::max(plane_spread, static_cast<double>(glm::length(at_depth(r, f) - on_plane)));
        // Where this ray is f from the eye's lens point: spread if the focus were a sphere.
        sphere_spread = std::max(sphere_spread, static_cast<double>(glm::length(r.origin + f * r.dir - on_sphere)));
    }
    CHECK(plane_spread < 1e-5);
    CHECK(sphere_spread > 0.01);
    CHECK(glm::length(on_plane - pin.origin) > f * 1.05f);  // the corner's ray length is f / cos > f
}

TEST_CASE("thin lens: a small bright sphere off the focal plane renders as a disk of the closed form's radius", "[render][camera][lens]") {
    // A sphere of radius rho at depth d on the axis, focus f: its image is the pinhole image
    // (radius ~ rho / d in image-plane units) widened by the blur disk (A/2)|d - f|/(f d). The
    // outermost lit pixel centre lies within a pixel diagonal of that radius. 96 x 96, 30 degrees:
    // a pixel is 2 tan(15 deg) / 96 = 0.00558 image-plane units.
    const int n = 96;
    const double pixel = 2.0 * std::tan(M_PI / 12.0) / n;
    const float aperture = 0.4f, rho = 0.02f;
    for (const auto& [d, f] : {std::pair{4.0f, 2.0f}, std::pair{2.0f, 4.0f}, std::pair{3.0f, 3.0f}}) {
        Scene scene = empty_scene(n, n);
        scene.camera = lens_camera(aperture, f);
        scene.background.color = glm::vec3(0.0f);
        Material light;
        light.type = Material::Type::Emissive;
        light.albedo = glm::vec3(0.0f);
        light.emission = glm::vec3(1.0f);
        add_object(scene, collision::Sphere{glm::vec3(0.0f, 0.0f, -d), rho}, add_material(scene, light), glm::mat4(1.0f), "bulb");
        const RenderResult r = render_with(scene, AccelKind::Bvh, 128, 1, 9);
        double lit = 0.0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                if (r.image.at(x, y).g > 0.0f) lit = std::max(lit, std::hypot(x + 0.5 - 0.5 * n, y + 0.5 - 0.5 * n));
        const double blur = 0.5 * aperture * std::abs(d - f) / (f * d) / pixel;
        const double image = rho / std::sqrt(d * d - rho * rho) / pixel;
        INFO("d " << d << " f " << f << ": outermost lit pixel at " << lit << " px; blur " << blur << " + sphere " << image << " px");
        CHECK(lit <= blur + image + 0.71);
        CHECK(lit >= blur + image - 1.5);  // edge pixels covered by a sliver may draw no sample
    }
}

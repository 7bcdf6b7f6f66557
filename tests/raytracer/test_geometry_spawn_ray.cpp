// pbrt's re-intersection test: a ray spawned from a hit never re-hits the surface it leaves.
// Convex closed objects alone in a scene, at scales 1e-4 to 1e5 and far from the origin,
// transformed and not: a ray leaving outward must hit nothing; a ray leaving inward (at least
// ~6 degrees off the surface) must reach the far side (for spheres a chord of at least a tenth of
// the size; for the faceted icosphere another triangle, far from the point it left). Hits come from both sides: rays from outside and from the centre.
#include <catch2/catch.hpp>

#include <random>

#include <glm/geometric.hpp>

#include "accel_test_scenes.hpp"
#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/geometry/intersect_object.hpp"

using namespace sweeptrace;

namespace {

// A direction with dot(w, n) of sign `side` and |cos| >= min_cos.
glm::vec3 leaving_direction(std::mt19937& rng, const glm::vec3& n, float side, float min_cos) {
    for (;;) {
        glm::vec3 w = test::random_direction(rng);
        const float c = glm::dot(w, n);
        if (std::abs(c) < min_cos) continue;
        return c * side > 0.0f ? w : -w;
    }
}

Scene single(Shape shape, const Transform& xf) {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.meshes.push_back(test::icosphere(3));
    scene.objects.push_back(test::object(std::move(shape), xf));
    return scene;
}

}  // namespace

TEST_CASE("spawn_ray: secondary rays never re-hit the surface they leave, 1e-4 to 1e5", "[geometry][spawn]") {
    std::mt19937 rng(5);
    int outward = 0, inward = 0;
    for (float scale : {1e-4f, 1e-2f, 1.0f, 1e3f, 1e5f}) {
        for (float offset_factor : {0.0f, 30.0f, 3e3f}) {
            for (int kind = 0; kind < 3; ++kind) {
                const glm::vec3 centre = scale * offset_factor * glm::vec3(1.0f, -0.7f, 0.4f);
                Scene scene;
                if (kind == 0) scene = single(collision::Sphere{centre, scale}, Transform{});
                if (kind == 1) scene = single(collision::Sphere{glm::vec3(0.0f), 1.0f}, test::random_transform(rng, centre, scale));
                if (kind == 2) scene = single(MeshInstance{0}, test::random_transform(rng, centre, scale));
                const BvhAccel accel(scene);
                // Smallest semi-axis: random_transform scales each axis by at least 0.6.
                const float size = (kind == 0 ? 1.0f : 0.6f) * scale;
                for (int i = 0; i < 200; ++i) {
                    const glm::vec3 dir = test::random_direction(rng);
                    const bool from_inside = i % 2 == 0;
                    const collision::Ray probe =
                        from_inside ? collision::Ray{centre, dir} : collision::Ray{centre - 10.0f * scale * dir, dir};
                    SurfaceHit hit;
                    if (!accel.intersect(probe, hit)) continue;
                    for (int k = 0; k < 4; ++k) {
                        INFO("scale " << scale << " offset " << offset_factor << " kind " << kind);
                        const collision::Ray out = spawn_ray(hit, leaving_direction(rng, hit.normal, 1.0f, 0.0f));
                        SurfaceHit again;
                        CHECK_FALSE(accel.intersect(out, again));
                        CHECK_FALSE(accel.occluded(out));
                        ++outward;
                        const collision::Ray in = spawn_ray(hit, leaving_direction(rng, hit.normal, -1.0f, 0.1f));
                        REQUIRE(accel.intersect(in, again));
                        const float travelled = glm::length(again.point - hit.point);
                        if (kind == 2) {
                            // A faceted surface: at ~6 degrees an inward ray may meet a
                            // neighbouring facet (the icosphere bends ~5 degrees per edge), but
                            // never its own triangle, and never near the point it left (a
                            // re-hit lands within the two error boxes and the offset).
                            CHECK(again.primitive != hit.primitive);
                            CHECK(travelled > 4.0f * (glm::length(hit.point_error) + glm::length(again.point_error)));
                        } else {
                            CHECK(travelled > 0.1f * size);
                        }
                        ++inward;
                    }
                }
            }
        }
    }
    CHECK(outward > 20000);
    CHECK(inward == outward);
}

TEST_CASE("spawn_ray_to: a shadow ray stops short of its target and sees blockers", "[geometry][spawn]") {
    std::mt19937 rng(8);
    int checked = 0, blocked_checked = 0;
    for (float scale : {1e-4f, 1.0f, 1e5f}) {
        // Two spheres side by side: from points on the first, aim at points on the second's
        // near side: unoccluded (the target's own surface must not count); with a third sphere
        // put between them: occluded.
        Scene scene;
        scene.materials.push_back(Material{});
        const glm::vec3 a(0.0f), b(4.0f * scale, 0.0f, 0.0f);
        scene.objects.push_back(test::object(collision::Sphere{a, scale}));
        scene.objects.push_back(test::object(collision::Sphere{b, scale}));
        Scene blocked = scene;
        blocked.objects.push_back(test::object(collision::Sphere{0.5f * (a + b), 0.5f * scale}));
        const BvhAccel open_accel(scene), blocked_accel(blocked);
        for (int i = 0; i < 500; ++i) {
            glm::vec3 da = test::random_direction(rng), db = test::random_direction(rng);
            da.x = std::abs(da.x) + 0.5f;  // the facing halves, well inside the line of sight
            db.x = -std::abs(db.x) - 0.5f;
            SurfaceHit from, to;
            if (!open_accel.intersect(collision::Ray{a, da}, from)) continue;
            if (!open_accel.intersect(collision::Ray{b, db}, to)) continue;
            const glm::vec3 towards = glm::normalize(to.point - from.point);
            // Facing each other, the target within 60 degrees of head-on (grazing chords: next test).
            if (glm::dot(towards, from.normal) <= 0.0f || glm::dot(-towards, to.normal) < 0.5f) continue;
            const collision::Ray shadow = spawn_ray_to(from, to.point, to.point_error, to.normal);
            INFO("scale " << scale);
            CHECK(shadow.tmax < 1.0f);
            CHECK(shadow.tmax > 0.99f);
            CHECK_FALSE(open_accel.occluded(shadow));
            const bool through_middle = glm::length(glm::vec3(0.0f, from.point.y + to.point.y, from.point.z + to.point.z)) <
                                        0.5f * scale;  // the segment's midpoint lies inside the blocker
            if (through_middle) {
                CHECK(blocked_accel.occluded(shadow));
                ++blocked_checked;
            }
            ++checked;
        }
    }
    CHECK(checked > 500);
    CHECK(blocked_checked > 50);
}

// Shadow rays between two points of one sphere (from inside a closed spherical light): the chord
// is exactly unoccluded, however grazing, and the sphere itself must never report it occluded
// (before both ends were offset, ~2.5 % of chords with cos < 0.1 at the target were). Chords from
// head-on down to cos ~ 1e-3, at scales 1e-4 to 1e5, centred and far from the origin; a small
// sphere put around the chord's midpoint must still occlude it.
TEST_CASE("spawn_ray_to: chords of one sphere are never occluded by it, grazing included", "[geometry][spawn]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    int checked = 0, grazing = 0, blocked_checked = 0;
    for (float scale : {1e-4f, 1e-2f, 1.0f, 1e3f, 1e5f}) {
        for (float offset_factor : {0.0f, 30.0f}) {
            const glm::vec3 centre = scale * offset_factor * glm::vec3(1.0f, -0.7f, 0.4f);
            Scene scene;
            scene.materials.push_back(Material{});
            scene.objects.push_back(test::object(collision::Sphere{centre, scale}));
            for (AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
                const std::unique_ptr<Accel> accel = make_accel(kind, scene);
                for (int i = 0; i < 400; ++i) {
                    // The second direction a random angle from the first, log-uniform down to
                    // ~2e-3 rad: the chord's cosine at both ends is sin(angle / 2).
                    const glm::vec3 da = test::random_direction(rng);
                    const float spread = std::pow(10.0f, -2.7f * u01(rng));
                    const glm::vec3 db = glm::normalize(da + spread * test::random_direction(rng));
                    SurfaceHit from, to;
                    REQUIRE(accel->intersect(collision::Ray{centre, da}, from));
                    REQUIRE(accel->intersect(collision::Ray{centre, db}, to));
                    const collision::Ray shadow = spawn_ray_to(from, to.point, to.point_error, to.normal);
                    const float cos_t = std::abs(glm::dot(to.normal, glm::normalize(to.point - from.point)));
                    INFO("scale " << scale << " offset " << offset_factor << " cos at target " << cos_t);
                    CHECK_FALSE(accel->occluded(shadow));
                    ++checked;
                    if (cos_t < 0.05f) ++grazing;
                    // A blocker around the midpoint, a quarter of the chord wide, inside the
                    // part of the segment that tmax keeps (cos >= 0.05: tmax > 0.999).
                    if (cos_t >= 0.05f && kind == AccelKind::Bvh) {
                        Scene blocked = scene;
                        const float chord = glm::length(to.point - from.point);
                        blocked.objects.push_back(
                            test::object(collision::Sphere{0.5f * (from.point + to.point), 0.25f * chord}));
                        CHECK(make_accel(AccelKind::Bvh, blocked)->occluded(shadow));
                        ++blocked_checked;
                    }
                }
            }
        }
    }
    CHECK(checked == 8000);
    CHECK(grazing > 1000);
    CHECK(blocked_checked > 1000);
}

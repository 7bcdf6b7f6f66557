// Motion blur end to end: rendering is deterministic with moving objects (threads, farm splits),
// an object that does not move renders as a still one, the native BVH agrees with brute force on
// random (ray, time) pairs, a linearly moving sphere matches the closed form of the swept
// sphere-line test within noise, and Embree's motion blur matches the native one within noise.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/swept.hpp"
#include "raytracer/accel/accel.hpp"
#include "raytracer/accel/brute_force_accel.hpp"
#include "raytracer/accel/bvh_accel.hpp"
#include "raytracer/image/diff.hpp"
#include "raytracer/image/partial_image.hpp"
#include "raytracer/render/camera.hpp"
#include "raytracer/render/renderer.hpp"
#include "motion_test_scenes.hpp"

using namespace sweeptrace;

namespace {

RenderOptions options(int spp, std::uint64_t seed, int threads, int first = 0) {
    RenderOptions o;
    o.spp = spp;
    o.first_sample = first;
    o.seed = seed;
    o.threads = threads;
    o.max_depth = 4;
    return o;
}

bool same_bits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

}  // namespace

TEST_CASE("motion render: 1 and 2 threads and any farm split give the same bits", "[motion][render][determinism]") {
    test::TempDir dir;
    const Scene scene = test::load_motion_scene(dir, 24, 16);
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
        const auto accel = make_accel(kind, scene);
        const RenderResult one = render(scene, *accel, options(6, 3, 1));
        const RenderResult two = render(scene, *accel, options(6, 3, 2));
        CHECK(same_bits(one.image, two.image));
        PartialImage a, b;
        a.sample_begin = 0;
        a.sample_end = 2;
        a.sums = render(scene, *accel, options(2, 3, 2, 0)).sums;
        b.sample_begin = 2;
        b.sample_end = 6;
        b.sums = render(scene, *accel, options(4, 3, 1, 2)).sums;
        RenderIdentity id;
        id.width = scene.film.width;
        id.height = scene.film.height;
        id.spp = 6;
        a.id = b.id = id;
        const PartialImage merged = merge_partials({b, a}, {"b", "a"});
        CHECK(merged.sums == one.sums);
        CHECK(same_bits(merged.mean(), one.image));
    }
}

TEST_CASE("motion render: zero motion with a shutter is the still scene, bit for bit", "[motion][render]") {
    test::TempDir dir;
    const Scene still = test::load_motion_scene(dir, 24, 16, false);
    const Scene zero = test::load_motion_scene(dir, 24, 16, true, true);
    REQUIRE(zero.camera.shutter);
    // Equal poses leave the objects still: the shutter and its time draws change nothing else.
    for (const Object& o : zero.objects) CHECK_FALSE(o.motion.moving());
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
        INFO("accel " << (kind == AccelKind::Bvh ? "bvh" : "embree"));
        const RenderResult a = render(still, *make_accel(kind, still), options(4, 9, 2));
        const RenderResult b = render(zero, *make_accel(kind, zero), options(4, 9, 2));
        CHECK(same_bits(a.image, b.image));
    }
    // And the moving scene is not (the test above could not pass by ignoring motion).
    const Scene moving = test::load_motion_scene(dir, 24, 16);
    CHECK_FALSE(same_bits(render(still, *make_accel(AccelKind::Bvh, still), options(4, 9, 2)).image,
                          render(moving, *make_accel(AccelKind::Bvh, moving), options(4, 9, 2)).image));
}

TEST_CASE("motion render: the BVH's and Embree's hits are brute force's on random (ray, time) pairs", "[motion][accel]") {
    test::TempDir dir;
    const Scene scene = test::load_motion_scene(dir, 16, 12);
    const auto brute = make_brute_force_accel(scene);
    const auto bvh = make_accel(AccelKind::Bvh, scene);
    const auto embree = make_accel(AccelKind::Embree, scene);
    std::mt19937 rng(25);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), t01(0.0f, 1.0f);
    int hits = 0, disagreements = 0;
    for (int i = 0; i < 20000; ++i) {
        // Rays from around the scene toward its moving middle, so most of them graze something.
        const glm::vec3 origin(3.0f * u(rng), 1.0f + 1.5f * u(rng), 3.0f * u(rng));
        const glm::vec3 target(1.5f * u(rng), 0.5f + 0.6f * u(rng), 1.2f * u(rng));
        const collision::Ray ray{origin, glm::normalize(target - origin)};
        const float time = t01(rng);
        SurfaceHit hb, hn, he;
        const bool b = brute->intersect(ray, time, hb);
        const bool n = bvh->intersect(ray, time, hn);
        const bool e = embree->intersect(ray, time, he);
        REQUIRE(n == b);
        REQUIRE(bvh->occluded(ray, time) == b);
        if (b) {
            ++hits;
            CHECK(hn.object == hb.object);
            CHECK(hn.t == Approx(hb.t).epsilon(1e-5));
        }
        // Embree finds mesh hits by its own triangle test and interpolates the instance itself:
        // the same answers except on a triangle edge or a grazing hit.
        if (e != b || (b && he.object != hb.object)) ++disagreements;
        CHECK(embree->occluded(ray, time) == e);
    }
    CHECK(hits > 5000);
    CHECK(disagreements <= 10);
}

TEST_CASE("motion render: fast motion cuts the shutter into time slices, which keep brute force's hits", "[motion][accel]") {
    // 64 small spheres each moving 8 diameters (swept spheres) and 8 boxes turning half a turn
    // (the pose path), so one box over the shutter would be 9 times too long.
    std::string objects;
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f), a(0.0f, 6.2831853f);
    for (int i = 0; i < 72; ++i) {
        const float x = u(rng), z = u(rng), angle = a(rng);
        const std::string at = std::string("[") + std::to_string(x) + ", 0.2, " + std::to_string(z) + "]";
        const std::string to = std::string("[") + std::to_string(x + 3.2f * std::cos(angle)) + ", 0.2, " + std::to_string(z + 3.2f * std::sin(angle)) + "]";
        if (i < 64)
            objects += R"(, { "type": "sphere", "radius": 0.2, "material": "m", "transform": [{ "translate": )" + at +
                       R"( }], "motion": { "close": [{ "translate": )" + to + " }] } }";
        else
            objects += R"(, { "type": "box", "size": [0.6, 0.2, 0.2], "material": "m", "motion": { "keyframes": [[{ "translate": )" + at +
                       R"( }], [{ "rotate": { "axis": [0, 1, 0], "degrees": 90 } }, { "translate": )" + at +
                       R"( }], [{ "rotate": { "axis": [0, 1, 0], "degrees": 180 } }, { "translate": )" + to + " }]] } }";
    }
    test::TempDir dir;
    const Scene scene = load_scene(dir.write("fast.json", R"({ "camera": { "position": [0, 4, 8], "look_at": [0, 0, 0], "shutter": [0, 1] },
  "film": { "width": 8, "height": 8 }, "materials": { "m": { "type": "diffuse", "albedo": [0.5, 0.5, 0.5] } },
  "objects": [ { "type": "quad", "corner": [-9, 0, -9], "edge_u": [0, 0, 18], "edge_v": [18, 0, 0], "material": "m" })" +
                                                     objects + "] }"));
    const BvhAccel bvh(scene);
    CHECK(bvh.time_slices() >= 8);
    const auto brute = make_brute_force_accel(scene);
    std::uniform_real_distribution<float> v(-1.0f, 1.0f), t01(0.0f, 1.0f);
    int hits = 0, ties = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 origin(6.0f * v(rng), 0.2f + 2.0f * (v(rng) + 1.0f), 6.0f * v(rng));
        const glm::vec3 target(4.0f * v(rng), 0.2f + 0.2f * v(rng), 4.0f * v(rng));
        const collision::Ray ray{origin, glm::normalize(target - origin)};
        const float time = i == 0 ? 0.0f : t01(rng);
        SurfaceHit hb, hn;
        const bool b = brute->intersect(ray, time, hb);
        REQUIRE(bvh.intersect(ray, time, hn) == b);
        REQUIRE(bvh.occluded(ray, time) == b);
        if (!b) continue;
        ++hits;
        INFO("time " << time << ": bvh object " << hn.object << " t " << hn.t << ", brute force " << hb.object << " t " << hb.t);
        CHECK(hn.t == hb.t);  // the same test on the same pose: the same float
        // Objects crossing each other may meet the ray at the same t: either is the nearest.
        ties += hn.object != hb.object ? 1 : 0;
    }
    CHECK(hits > 10000);
    CHECK(ties <= 5);
}

// The closed form: a black sphere crossing a uniform white background (radiance 1) seen by a
// pinhole camera with a box filter. A camera ray through film point p misses the sphere for
// 1 - (t1 - t0) of the shutter, [t0, t1] = collision::sweep_interval(sphere at open, motion, ray),
// so the pixel's expected value is that averaged over its area: integrated here by a 32 x 32
// midpoint rule per pixel (the integrand is continuous; its error is far below the noise).
TEST_CASE("motion render: a moving sphere matches the swept sphere-line closed form within noise", "[motion][render][truth]") {
    test::TempDir dir;
    const Scene scene = load_scene(dir.write("truth.json", R"({
  "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 30, "shutter": [0, 1] },
  "film": { "width": 48, "height": 24, "spp": 64, "max_depth": 1 },
  "background": { "color": [1, 1, 1] },
  "materials": { "black": { "type": "diffuse", "albedo": [0, 0, 0] } },
  "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "black",
                 "transform": [{ "translate": [-1.2, 0.1, 0] }], "motion": { "close": [{ "translate": [1.0, -0.2, 0.3] }] } } ]
})"));
    const collision::Sphere open{{-1.2f, 0.1f, 0.0f}, 0.5f};
    const glm::vec3 motion(2.2f, -0.3f, 0.3f);
    const CameraModel camera(scene.camera, scene.film.width, scene.film.height);
    Image truth(scene.film.width, scene.film.height);
    constexpr int kQ = 32;
    for (int y = 0; y < truth.height; ++y)
        for (int x = 0; x < truth.width; ++x) {
            double sum = 0.0;
            for (int j = 0; j < kQ; ++j)
                for (int i = 0; i < kQ; ++i) {
                    const collision::Ray ray = camera.generate(float(x) + (i + 0.5f) / kQ, float(y) + (j + 0.5f) / kQ, 0.0f, 0.0f);
                    const collision::TimeInterval seen = collision::sweep_interval(open, motion, ray);
                    sum += 1.0 - (seen.hit ? double(seen.t1) - double(seen.t0) : 0.0);
                }
            truth.pixels[std::size_t(y) * truth.width + x] = glm::vec3(float(sum / (kQ * kQ)));
        }
    // The swept sphere covers a good part of the image: the test is about the blur, not the sky.
    int blurred = 0;
    for (const glm::vec3& p : truth.pixels) blurred += (p.x > 0.05f && p.x < 0.95f) ? 1 : 0;
    REQUIRE(blurred > 150);

    // Each sample is 0 or 1 (box filter, weight 1), so a pixel mean of n samples has variance at
    // most p (1 - p) / n with p its truth (stratification only lowers it): the null variance,
    // which keeps a block the render happened to see uncovered (estimated variance 0) testable.
    constexpr int kSpp = 64;
    Image null_variance(truth.width, truth.height);
    for (std::size_t i = 0; i < truth.pixels.size(); ++i)
        null_variance.pixels[i] = truth.pixels[i] * (glm::vec3(1.0f) - truth.pixels[i]) / float(kSpp);
    BlockTestOptions opt;
    opt.block = 4;
    opt.golden_is_8bit = false;
    opt.null_variance = &null_variance;
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
        const auto accel = make_accel(kind, scene);
        RenderOptions o = options(kSpp, 11, 0);
        o.max_depth = 1;
        const RenderResult r = render(scene, *accel, o);
        const BlockTestResult t = block_test(truth, r.image, r.variance, opt);
        INFO((kind == AccelKind::Bvh ? "bvh: " : "embree: ") << t.summary());
        CHECK(t.pass());
        // And the test can fail: the sphere still at its open pose is far outside the noise.
        const Scene still_scene = [&] {
            Scene s = scene;
            s.objects[0].motion = Motion{};
            return s;
        }();
        const RenderResult wrong = render(still_scene, *make_accel(kind, still_scene), o);
        CHECK_FALSE(block_test(truth, wrong.image, wrong.variance, opt).pass());
    }
}

TEST_CASE("motion render: Embree's motion blur and the native BVH's agree within noise", "[motion][render][embree]") {
    test::TempDir dir;
    const Scene scene = test::load_motion_scene(dir, 48, 32);
    const RenderResult native = render(scene, *make_accel(AccelKind::Bvh, scene), options(64, 1, 0));
    const RenderResult embree = render(scene, *make_accel(AccelKind::Embree, scene), options(64, 2, 0));
    BlockTestOptions opt;
    opt.block = 8;
    opt.golden_is_8bit = false;
    opt.null_variance = &native.variance;
    opt.reference_noise_ratio = 1.0;
    const BlockTestResult t = block_test(native.image, embree.image, embree.variance, opt);
    INFO(t.summary());
    CHECK(t.pass());
}
